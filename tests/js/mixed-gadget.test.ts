// The Section 3.1 gadget of the teaching demo (web/demo/src/teach/mixed/build.ts):
// on every formula of up to three variables and three clauses of one to three
// literals that the builder lays out, and on a fixed random sample over four to
// six variables, the library's exact optimum of min-mixed-vertices equals the
// gadget's floor (its always-mixed centre points) exactly when the formula is
// satisfiable, every assignment's triangulation has floor + (its false clauses)
// mixed vertices, and the fans of the optimum read back as a satisfying
// assignment.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { randomFormulas, smallFormulas } from './smallFormulas.ts';
import { parseCnf, satisfyingAssignment } from '../../web/demo/src/teach/formula.ts';
import { buildMixedGadget, MixedLayoutError } from '../../web/demo/src/teach/mixed/build.ts';
import { certifyMixed, mapFanSectors, readMixedAssignment, unsatisfiedClauses } from '../../web/demo/src/teach/mixed/check.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

const build = (text: string) => buildMixedGadget(parseCnf(text, 1, 3, 'x'));

function check(text: string): { sat: boolean; points: number } {
  const f = parseCnf(text, 1, 3, 'x');
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
  return { sat, points: g.points.length / 3 };
}

/** Checks every formula the builder accepts; counts what was accepted. */
function checkAll(texts: string[]) {
  const tally = { accepted: 0, unsatisfiable: 0, threeLiteral: 0, threeLiteralUnsat: 0, inThreeClauses: 0, maxPoints: 0 };
  for (const text of texts) {
    try {
      build(text);
    } catch (e) {
      if (e instanceof MixedLayoutError) continue;
      throw e;
    }
    const f = parseCnf(text, 1, 3, 'x');
    const { sat, points } = check(text);
    const three = f.clauses.some((c) => c.length === 3);
    const occurrences = new Array<number>(f.names.length).fill(0);
    f.clauses.forEach((c) => c.forEach((l) => occurrences[l.variable]!++));
    tally.accepted++;
    if (!sat) tally.unsatisfiable++;
    if (three) tally.threeLiteral++;
    if (three && !sat) tally.threeLiteralUnsat++;
    if (occurrences.some((o) => o >= 3)) tally.inThreeClauses++;
    tally.maxPoints = Math.max(tally.maxPoints, points);
  }
  return tally;
}

describe('mixed vertices gadget (Section 3.1)', () => {
  test('formulas that cannot be laid out are refused with a reason', () => {
    expect(() => build('x | y, x | !y')).toThrow(/turn both ways/);
    expect(() => build('x | y, y | z, x | z')).toThrow(/turn both ways/);
    expect(() => build('x | y | z, !x | !y')).toThrow(/turn both ways/);
    expect(() => build('x | y | z, !x | y | !z')).toThrow(/same three variables/);
    expect(() => build('x, x | y, x | !z, !x | w, x | v, !x | u, x | t')).toThrow(/in 7 clauses/);
    expect(() => build('x, x, x')).toThrow(MixedLayoutError);
    expect(build('x | y, !x | !y').clauses.length).toBe(2);
    expect(build('x | y | z, !x, !y, !z').clauses.length).toBe(4);
  });

  test('every accepted formula over 3 variables with up to 3 clauses of up to 3 literals: optimum = floor iff satisfiable, read back', () => {
    const t = checkAll(smallFormulas(3));
    expect(t.accepted).toBeGreaterThan(1300);
    expect(t.unsatisfiable).toBeGreaterThan(90);
    expect(t.threeLiteral).toBeGreaterThan(450);
    expect(t.threeLiteralUnsat).toBeGreaterThan(20);
    expect(t.inThreeClauses).toBeGreaterThan(350);
    expect(t.maxPoints).toBeLessThan(200);
  });

  test('a fixed random sample over 4 to 6 variables, mostly three-literal clauses', () => {
    const t = checkAll(randomFormulas(300));
    expect(t.accepted).toBeGreaterThan(50);
    expect(t.threeLiteral).toBeGreaterThan(40);
  });

  test('chosen formulas of up to six variables, several parts side by side', () => {
    for (const [text, sat] of [
      ['x | y | z, !x | y, !y | w, !z', true],
      ['x | y | z, !x | w | v, !y, !z, !w, !v', false],
      ['x | y | z, !x | !y | !w, !z, w', true],
      ['a | b | c, !a | d | e, !b, !c | !d, !e', true],
      ['a | b, !b | c, c | !d, d | e, !e | f, !a, !f', true],
      ['a | b | c, !a, !b, !c, d | e | f', false],
      ['a, b, c, d, e, !f', true],
    ] as const) expect(check(text).sat, text).toBe(sat);
  });
});
