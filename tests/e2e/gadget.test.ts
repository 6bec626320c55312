// The gadget builder of the teaching demo (web/demo/src/teach/): formulas parse,
// and the terrain built from a formula has, as the library solves it, the optimum
// the paper's reduction predicts (constant + the MAX-2-SAT optimum), read back
// from the pools. The views' other numbers come from terrain.explain and are
// checked in tests/e2e/teach.test.ts.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { countSatisfied, FormulaError, maxSatisfiable, parseFormula } from '../../web/demo/src/teach/formula.ts';
import { buildGadget } from '../../web/demo/src/teach/gadget/build.ts';
import { certify, mapCells, readBack } from '../../web/demo/src/teach/gadget/check.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

describe('hardness gadget', () => {
  test('formulas parse, and bad ones say why', () => {
    const g = parseFormula('(x1 ∨ ¬x2) ∧ (not x2 or x3); ~x3 | -x1\n!!x1 | x2');
    expect(g.names).toEqual(['x1', 'x2', 'x3']);
    expect(g.clauses.map((c) => c.map((l) => `${l.negated ? '!' : ''}${g.names[l.variable]}`).join('|'))).toEqual(['x1|!x2', '!x2|x3', '!x3|!x1', 'x1|x2']);
    expect(() => parseFormula('x1 | x1')).toThrow(FormulaError);
    expect(() => parseFormula('x1')).toThrow(/two literals/);
    expect(() => parseFormula('x1 | 2x')).toThrow(/not a literal/);
    expect(() => parseFormula('')).toThrow(/at least one clause/);
  });

  test('the gadget of a formula: optimum = constant + MAX-2-SAT optimum, read back from the pools', () => {
    for (const text of ['x1 | x2, !x1 | x2, x1 | !x2, !x1 | !x2, x2 | x3, !x3 | x1, !x2 | !x3', 'a | b, !b | c, !c | d, !d | !a, a | c', 'p | q']) {
      const formula = parseFormula(text);
      const g = buildGadget(formula);
      using terrain = hodt.terrain(g.points);
      const map = mapCells(g, terrain.quads);
      const sol = terrain.solve('max-convex-edges', { method: 'exact' });
      const best = maxSatisfiable(formula).best;
      const cert = certify(formula, (c) => terrain.evaluate(c)['max-convex-edges'], g, map, sol.choice);
      expect(cert.constant, text).not.toBeNull();
      expect(sol.value, text).toBe(cert.constant! + best);
      expect(countSatisfied(formula, readBack(g, map, sol.choice).assignment), text).toBe(best);
    }
  });
});
