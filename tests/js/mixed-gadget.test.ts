// The Section 3.1 gadget of the teaching demo (web/demo/src/teach/mixedGadget.ts):
// on every formula of up to three variables and three clauses that the builder
// lays out, the library's exact optimum of min-mixed-vertices equals the gadget's
// floor (its always-mixed fan centres) exactly when the formula is satisfiable,
// every assignment's triangulation has floor + (its false clauses) mixed
// vertices, and the fans of the optimum read back as a satisfying assignment.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { smallFormulas } from './smallFormulas.ts';
import { parseCnf, satisfyingAssignment } from '../../web/demo/src/teach/formula.ts';
import { ChainLayoutError } from '../../web/demo/src/teach/chainLayout.ts';
import { buildMixedGadget } from '../../web/demo/src/teach/mixedGadget.ts';
import { certifyMixed, mapFanSectors, readMixedAssignment, unsatisfiedClauses } from '../../web/demo/src/teach/mixedCheck.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

function check(text: string): { sat: boolean } {
  const f = parseCnf(text, 1, 2, 'x');
  const g = buildMixedGadget(f);
  using terrain = hodt.terrain(g.points);
  const map = mapFanSectors(g, terrain.quads);
  const solution = terrain.solve('min-mixed-vertices', { method: 'exact' });
  expect(solution.optimal, text).toBe(true);
  const sat = satisfyingAssignment(f) !== null;
  // The proof's prediction: the floor exactly when satisfiable.
  if (sat) expect(solution.value, text).toBe(g.floor);
  else expect(solution.value, text).toBeGreaterThan(g.floor);
  expect(certifyMixed(g, map, terrain.numQuads, (c) => terrain.evaluate(c)['min-mixed-vertices']).wrong, text).toEqual([]);
  const read = readMixedAssignment(g, map, solution.choice);
  if (sat) {
    expect(unsatisfiedClauses(f, read.assignment), text).toBe(0);
    expect(read.disagreeing.every((d) => d === 0), text).toBe(true);
  }
  return { sat };
}

describe('mixed vertices gadget (Section 3.1)', () => {
  test('formulas that cannot be laid out are refused with a reason', () => {
    const build = (t: string) => buildMixedGadget(parseCnf(t, 1, 3, 'x'));
    expect(() => build('x | y | z')).toThrow(/three literals/);
    expect(() => build('x | y, !x | z, x')).toThrow(/in 3 clauses/);
    expect(() => build('x | y, x | !y')).toThrow(/share two variables/);
    expect(() => build('x | y, y | z, z | !x')).toThrow(/cycle/);
    expect(() => build('x | y, !x | !y, x | !y')).toThrow(ChainLayoutError);
    expect(build('x | y, !x | !y').clauses.length).toBe(2);
  });

  test('every accepted formula up to 3 variables and 3 clauses: optimum = floor iff satisfiable, read back', () => {
    let accepted = 0, unsatisfiable = 0;
    for (const text of smallFormulas()) {
      try {
        buildMixedGadget(parseCnf(text, 1, 2, 'x'));
      } catch (e) {
        if (e instanceof ChainLayoutError) continue;
        throw e;
      }
      accepted++;
      if (!check(text).sat) unsatisfiable++;
    }
    expect(accepted).toBeGreaterThan(380);
    expect(unsatisfiable).toBeGreaterThan(30);
  });

  test('longer chains of up to six variables, several chains on one line', () => {
    for (const [text, sat] of [
      ['a | b, !b | c, c | !d, d | e, !e | f, !a, !f', true],
      ['a | b, !b | c, !c | d, !d | e, !e | f, !a, !f', false],
      ['a | b, c | d, e | f, !a, !b, !c', false],
      ['a | !b, !a | b', true],
      ['a, b, c, d, e, !f', true],
    ] as const) expect(check(text).sat, text).toBe(sat);
  });
});
