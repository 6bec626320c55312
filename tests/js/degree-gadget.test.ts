// The Section 3.2 gadget of the teaching demo (web/demo/src/teach/degree/build.ts):
// on every formula of up to three variables and three clauses that the builder
// lays out, the library's exact optimum of minmax-degree is at most the bound d
// exactly when the formula is satisfiable, and every assignment's triangulation
// reaches d exactly when the assignment satisfies the formula.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { smallFormulas } from './smallFormulas.ts';
import { FormulaError, parseCnf, satisfyingAssignment } from '../../web/demo/src/teach/formula.ts';
import { buildDegreeGadget, DegreeLayoutError } from '../../web/demo/src/teach/degree/build.ts';
import { certifyDegree, mapDegreeCells, readDegreeAssignment, satisfies } from '../../web/demo/src/teach/degree/check.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

describe('max degree gadget (Section 3.2)', () => {
  test('formulas with one to three literals per clause parse, and bad ones say why', () => {
    const f = parseCnf('(x ∨ ¬y ∨ z) ∧ !x; y', 1, 3, 'x | y');
    expect(f.names).toEqual(['x', 'y', 'z']);
    expect(f.clauses.map((c) => c.length)).toEqual([3, 1, 1]);
    expect(() => parseCnf('x | y | z | w', 1, 3, 'x')).toThrow(/one to three literals/);
    expect(() => parseCnf('x | !x', 1, 3, 'x')).toThrow(FormulaError);
  });

  test('formulas that cannot be laid out are refused with a reason', () => {
    expect(() => buildDegreeGadget(parseCnf('x | y | z', 1, 3, 'x'))).toThrow(/three literals/);
    expect(() => buildDegreeGadget(parseCnf('x | y, !x | z, x', 1, 3, 'x'))).toThrow(/in 3 clauses/);
    expect(() => buildDegreeGadget(parseCnf('x | y, x | !y', 1, 3, 'x'))).toThrow(/share two variables/);
    expect(() => buildDegreeGadget(parseCnf('x | y, !x | !y, x | !y', 1, 3, 'x'))).toThrow(DegreeLayoutError);
    expect(buildDegreeGadget(parseCnf('x | y, !x | !y', 1, 3, 'x')).clauses.length).toBe(2);
    expect(() => buildDegreeGadget(parseCnf('x | y, y | z, z | !x', 1, 3, 'x'))).toThrow(/cycle/);
  });

  test('every accepted formula up to 3 variables and 3 clauses: optimum <= d iff satisfiable', () => {
    let accepted = 0, unsatisfiable = 0;
    for (const text of smallFormulas()) {
      const f = parseCnf(text, 1, 3, 'x');
      let g;
      try {
        g = buildDegreeGadget(f);
      } catch (e) {
        if (e instanceof DegreeLayoutError) continue;
        throw e;
      }
      accepted++;
      using terrain = hodt.terrain(g.points, { maxEdge: g.maxEdge });
      const map = mapDegreeCells(g, terrain.quads);
      expect(map.otherQuadsAtFixedPoints, text).toBe(0);
      const solution = terrain.solve('minmax-degree', { method: 'exact' });
      expect(solution.optimal, text).toBe(true);
      const sat = satisfyingAssignment(f) !== null;
      if (!sat) unsatisfiable++;
      expect(solution.value <= g.bound, text).toBe(sat);
      expect(certifyDegree(g, map, terrain.numQuads, (c) => terrain.evaluate(c)['minmax-degree']).wrong, text).toEqual([]);
      if (sat) expect(satisfies(f, readDegreeAssignment(g, map, solution.choice).assignment), text).toBe(true);
    }
    expect(accepted).toBeGreaterThan(575);
    expect(unsatisfiable).toBeGreaterThan(5);
  });

  test('longer chains of up to six variables, several chains on one line', () => {
    for (const [text, sat] of [
      ['a | b, !b | c, c | !d, d | e, !e | f, !a, !f', true],
      ['a | b, !b | c, !c | d, !d | e, !e | f, !a, !f', false],
      ['a | b, c | d, e | f, !a, !b, !c', false],
      ['a, b, c, d, e, !f', true],
    ] as const) {
      const f = parseCnf(text, 1, 2, 'x');
      const g = buildDegreeGadget(f);
      using terrain = hodt.terrain(g.points, { maxEdge: g.maxEdge });
      const solution = terrain.solve('minmax-degree', { method: 'exact' });
      expect(satisfyingAssignment(f) !== null, text).toBe(sat);
      expect(solution.optimal, text).toBe(true);
      expect(solution.value <= g.bound, text).toBe(sat);
    }
  });
});
