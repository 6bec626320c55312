// The teaching views' TypeScript models (web/demo/src/teach/) against the
// library, in Node: the convex-edge factors count what the library counts, the
// 2-SAT steps reproduce the library's trace, and Baker's bounds equal the
// library's approximation bound.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { bakerLambda, bakerShift, convexEdgeModel, evaluateFactors, maxSum, nonMixedModel } from '../../web/demo/src/teach/convexModel.ts';
import { analyseStep, buildPairModel, PAIR_OBJECTIVES } from '../../web/demo/src/teach/pairModel.ts';
import { readStructure } from '../../web/demo/src/teach/structure.ts';
import { edgeShape } from '../../web/demo/src/teach/geometry.ts';
import { countSatisfied, FormulaError, maxSatisfiable, parseFormula } from '../../web/demo/src/teach/formula.ts';
import { buildGadget, f } from '../../web/demo/src/teach/gadget.ts';
import { certify, mapCells, readBack } from '../../web/demo/src/teach/gadgetCheck.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

function randomPoints(n: number, seed: number): Float64Array {
  let s = seed >>> 0;
  const random = () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return Float64Array.from({ length: 3 * n }, (_, i) => (i % 3 === 2 ? 12 : 100) * random());
}

describe('teaching models', () => {
  test('convex-edge factors count the convex edges of any choice', () => {
    for (const seed of [1, 2, 3]) {
      using terrain = hodt.terrain(randomPoints(60, seed));
      const s = readStructure(terrain);
      const g = convexEdgeModel(s);
      for (let k = 0; k < 10; k++) {
        const choice = Uint8Array.from({ length: s.m }, (_, q) => (q * 7 + k * 13 + seed) % 3 === 0 ? 1 : 0);
        expect(evaluateFactors(g, choice)).toBe(terrain.evaluate(choice)['max-convex-edges']);
      }
      const best = maxSum(g, g.factors.map((_, k) => k));
      expect(best.value).toBe(terrain.solve('max-convex-edges', { method: 'exact' }).value);
    }
  });

  test("Baker's shifts give the library's bound", () => {
    for (const [seed, epsilon] of [[4, 0.3], [5, 0.5], [6, 0.2]] as const) {
      using terrain = hodt.terrain(randomPoints(80, seed));
      const s = readStructure(terrain);
      const g = convexEdgeModel(s);
      const sol = terrain.solve('max-convex-edges', { method: 'approx', epsilon });
      const lambda = bakerLambda(g, s.quadDepth, epsilon);
      expect(sol.details).toContain(`lambda ${lambda},`);
      const shifts = Array.from({ length: lambda }, (_, i) => bakerShift(g, s.quadDepth, lambda, i));
      expect(Math.min(...shifts.map((x) => x.bound))).toBe(sol.bound ?? sol.value);
      expect(Math.max(...shifts.map((x) => x.value))).toBeLessThanOrEqual(sol.value);
    }
  });

  test('non-mixed vertex factors and their Baker bound match the library', () => {
    for (const [seed, epsilon] of [[9, 0.3], [10, 0.5]] as const) {
      using terrain = hodt.terrain(randomPoints(70, seed));
      const s = readStructure(terrain);
      const { graph, interior } = nonMixedModel(s);
      for (let k = 0; k < 6; k++) {
        const choice = Uint8Array.from({ length: s.m }, (_, q) => ((q * 5 + k * 11 + seed) % 3 === 0 ? 1 : 0));
        expect(interior - evaluateFactors(graph, choice)).toBe(terrain.evaluate(choice)['min-mixed-vertices']);
      }
      const sol = terrain.solve('min-mixed-vertices', { method: 'approx', epsilon });
      const lambda = bakerLambda(graph, s.quadDepth, epsilon);
      expect(sol.details).toContain(`lambda ${lambda},`);
      const shifts = Array.from({ length: lambda }, (_, i) => bakerShift(graph, s.quadDepth, lambda, i));
      expect(interior - Math.min(...shifts.map((x) => x.bound))).toBe(sol.bound ?? sol.value);
    }
  });

  test('each 2-SAT step reproduces the library trace', () => {
    for (const seed of [7, 8]) {
      using terrain = hodt.terrain(randomPoints(50, seed));
      const s = readStructure(terrain);
      for (const id of PAIR_OBJECTIVES) {
        const sol = terrain.solve(id, { trace: true });
        const model = buildPairModel(s, id);
        for (const step of sol.trace) {
          const a = analyseStep(model, s.m, step.threshold);
          expect(a.immediateNo, `${id} ${step.threshold}`).toBe(step.immediateNo);
          expect(a.satisfiable, `${id} ${step.threshold}`).toBe(step.satisfiable);
          if (!step.immediateNo) {
            expect(a.forced.length).toBe(step.forced);
            expect(a.clauses).toBe(step.clauses);
          }
        }
        // The same candidate, up to the last bits of the doubles (atan, sqrt).
        expect(Math.min(...model.candidates.map((c) => Math.abs(c - sol.value) / Math.max(1, sol.value)))).toBeLessThan(1e-12);
      }
    }
  });

  test('formulas parse, and bad ones say why', () => {
    const g = parseFormula('(x1 ∨ ¬x2) ∧ (not x2 or x3); ~x3 | -x1\n!!x1 | x2');
    expect(g.names).toEqual(['x1', 'x2', 'x3']);
    expect(g.clauses.map((c) => c.map((l) => `${l.negated ? '!' : ''}${g.names[l.variable]}`).join('|'))).toEqual(['x1|!x2', '!x2|x3', '!x3|!x1', 'x1|x2']);
    expect(() => parseFormula('x1 | x1')).toThrow(FormulaError);
    expect(() => parseFormula('x1')).toThrow(/two literals/);
    expect(() => parseFormula('x1 | 2x')).toThrow(/not a literal/);
    expect(() => parseFormula('')).toThrow(/at least one clause/);
  });

  test('the heights make every quad a convex and a reflex diagonal, and a shared edge convex unless both quads are convex', () => {
    // Edge shapes are unchanged by adding a plane, and f at (x + a, y + b) is f
    // plus a plane: one spot decides for the whole grid.
    expect(f(0, 0) + f(1, 1) - f(1, 0) - f(0, 1)).toBe(1);
    // The edge (0, 0)-(0, 1) between the quads left and right of it: the apex of
    // each side's triangle is the corner its convex (SW-NE) or reflex diagonal
    // leaves on that edge.
    const pts = [[0, 0], [0, 1], [-1, 0], [-1, 1], [1, 1], [1, 0]];
    const xyz = Float64Array.from(pts.flatMap(([x, y]) => [x!, y!, f(x!, y!)]));
    const left = { convex: 2, reflex: 3 };
    const right = { convex: 4, reflex: 5 };
    for (const l of ['convex', 'reflex'] as const) {
      for (const r of ['convex', 'reflex'] as const) {
        const shape = edgeShape(xyz, 0, 1, left[l], right[r]);
        expect(shape, `${l} | ${r}`).toBe(l === 'convex' && r === 'convex' ? 1 : 0);
      }
    }
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
