// The models of the demo's teaching views (web/demo/src/teach/*/model.ts): what
// each view shows, computed without the DOM from the library's answers in Node.
import { loadHodt, OBJECTIVE_IDS, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { jitteredGridPoints } from '../../web/demo/src/terrains/jitteredGrid.ts';
import { smallTerrain } from '../../web/demo/src/teach/common.ts';
import { MAX_BRUTE_QUADS, rankChoices, rankTerrain, valueCounts } from '../../web/demo/src/teach/brute/model.ts';
import { choiceAt, counterText, explainSearch, lastPosition, quadPairs, searchRows, testAt } from '../../web/demo/src/teach/sat/model.ts';
import { pitsGone, splitByDelaunay, startSolve } from '../../web/demo/src/teach/order/model.ts';
import { bestShift, cutsOf, isCut, lastPosition as bakerLast, shiftAt, startRun, withOutcome } from '../../web/demo/src/teach/baker/model.ts';
import { readStructure } from '../../web/demo/src/teach/structure.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

describe('All triangulations (brute/model.ts)', () => {
  test('choices are ranked best first for the sense, ties by mask', () => {
    const n = OBJECTIVE_IDS.length;
    const k = OBJECTIVE_IDS.indexOf('max-convex-edges');
    // m = 2: masks 0..3 with values 5, 7, 5, 1 for the objective.
    const all = new Float64Array(4 * n);
    [5, 7, 5, 1].forEach((v, mask) => (all[mask * n + k] = v));
    expect(rankChoices(all, 2, 'max-convex-edges', 'max')).toEqual([
      { mask: 1, value: 7 },
      { mask: 0, value: 5 },
      { mask: 2, value: 5 },
      { mask: 3, value: 1 },
    ]);
    expect(rankChoices(all, 2, 'max-convex-edges', 'min').map((x) => x.mask)).toEqual([3, 0, 2, 1]);
    expect(valueCounts(rankChoices(all, 2, 'max-convex-edges', 'max'))).toEqual([
      [7, 1],
      [5, 2],
      [1, 1],
    ]);
  });

  test('on the view’s small terrain the first is the brute-force optimum and Delaunay is mask 0', () => {
    using terrain = hodt.terrain(smallTerrain(hodt, 16, 7, 7, 11));
    for (const [id, sense] of [['max-convex-edges', 'max'], ['min-mixed-vertices', 'min']] as const) {
      const s = rankTerrain(terrain, id, sense);
      const model = s.model!;
      expect(model.order).toHaveLength(2 ** terrain.numQuads);
      expect(model.best).toBe(terrain.solve(id, { method: 'brute-force' }).value);
      expect(model.order.find((x) => x.mask === 0)!.value).toBe(terrain.evaluate(new Uint8Array(terrain.numQuads))[id]);
      const values = model.order.map((x) => x.value);
      expect(values).toEqual([...values].sort((a, b) => (sense === 'min' ? a - b : b - a)));
    }
  });

  test('a terrain with too many quads is refused with the count', () => {
    using terrain = hodt.terrain(jitteredGridPoints(64, 15));
    expect(terrain.numQuads).toBeGreaterThan(MAX_BRUTE_QUADS);
    const s = rankTerrain(terrain, 'max-convex-edges', 'max');
    expect(s.model).toBeNull();
    expect(s.message).toContain(`${terrain.numQuads} flippable quads`);
  });
});

describe('2-SAT search (sat/model.ts)', () => {
  test('the search on the view’s example: positions, binary search rows and clause pairs follow the library’s trace', () => {
    using terrain = hodt.terrain(jitteredGridPoints(64, 15));
    const s = explainSearch(terrain, 'minmax-edge-area-ratio');
    expect(s.error).toBeNull();
    const search = s.search!;
    const tests = search.search.tests;
    expect(tests.length).toBeGreaterThan(1);
    expect(lastPosition(search)).toBe(tests.length + 1);
    expect(counterText(search, 0)).toBe('start');
    expect(counterText(search, 2)).toBe(`step 2 of ${tests.length}`);
    expect(counterText(search, tests.length + 1)).toBe('done');
    expect(testAt(search, 0)).toBeNull();
    expect(testAt(search, 1)).toBe(tests[0]);
    expect(choiceAt(search, 0)).toEqual(new Uint8Array(search.structure.m));
    expect(choiceAt(search, tests.length + 1)).toBe(search.solution.choice);
    // Each test lies in the interval still open, and the optimum in every one.
    const optimum = search.search.candidates.indexOf(search.solution.value);
    expect(optimum).toBeGreaterThanOrEqual(0);
    const rows = searchRows(search);
    expect(rows).toHaveLength(tests.length);
    rows.forEach((r, i) => {
      expect(r.rank).toBe(search.search.candidates.indexOf(tests[i]!.threshold));
      expect(r.rank).toBeGreaterThanOrEqual(r.lo);
      expect(r.rank).toBeLessThanOrEqual(r.hi);
      expect(optimum).toBeGreaterThanOrEqual(r.lo);
      expect(optimum).toBeLessThanOrEqual(r.hi);
      if (i > 0) expect(r.hi - r.lo).toBeLessThan(rows[i - 1]!.hi - rows[i - 1]!.lo);
    });
    // Every clause between two quads is one pair, listed once, smaller quad first.
    for (const t of tests) {
      const pairs = quadPairs(t);
      const keys = pairs.map(([q, r]) => `${q},${r}`);
      expect(new Set(keys).size).toBe(keys.length);
      for (const [q, r] of pairs) expect(q).toBeLessThan(r);
      for (let k = 0; k < t.clauses.length; k += 2) {
        const [q, r] = [t.clauses[k]! >> 1, t.clauses[k + 1]! >> 1].sort((a, b) => a - b);
        if (q !== r) expect(keys).toContain(`${q},${r}`);
      }
    }
    expect(tests.some((t) => quadPairs(t).length > 0)).toBe(true);
  });
});

describe('Order k (order/model.ts)', () => {
  test('the optimum’s edges split into Delaunay’s and new ones; gone pits are Delaunay’s the optimum lacks', () => {
    // A square 0 1 2 3 with Delaunay diagonal 0-2; the optimum uses 1-3.
    const delaunay = Uint32Array.of(0, 1, 2, 0, 2, 3);
    const optimum = Uint32Array.of(0, 1, 3, 1, 2, 3);
    const { kept, changed } = splitByDelaunay(delaunay, optimum);
    const pairs = (a: number[]) => Array.from({ length: a.length / 2 }, (_, i) => [a[2 * i]!, a[2 * i + 1]!].sort((x, y) => x - y).join('-'));
    expect(pairs(changed).sort()).toEqual(['1-3', '1-3']);
    expect(pairs(kept).sort()).toEqual(['0-1', '0-3', '1-2', '2-3']);
    const s = { ...startSolve(2, 'min-local-minima'), minima: [4], delaunayMinima: [4, 7, 9] };
    expect(pitsGone(s)).toEqual([7, 9]);
  });
});

describe('Baker layers (baker/model.ts)', () => {
  test('the cuts of each shift are every lambda-th layer boundary, and the run reads the library’s explanation', () => {
    // Eight layers have seven boundaries (0|1 to 6|7).
    expect([0, 1, 2].map((shift) => cutsOf(shift, 8, 3))).toEqual([[0, 3, 6], [1, 4], [2, 5]]);
    for (let shift = 0; shift < 3; shift++) {
      const cuts = cutsOf(shift, 8, 3);
      for (let l = 0; l < 7; l++) expect(isCut(l, l + 1, shift, 3), `shift ${shift} layer ${l}`).toBe(cuts.includes(l));
      expect(cuts.every((l) => l % 3 === shift)).toBe(true);
    }
    // Two quads several layers apart are cut by every shift.
    for (let shift = 0; shift < 3; shift++) expect(isCut(0, 3, shift, 3)).toBe(true);

    using terrain = hodt.terrain(jitteredGridPoints(100, 1));
    const explained = terrain.explain('max-convex-edges', { method: 'approx', epsilon: 0.34 });
    const start = startRun(readStructure(terrain), 'max-convex-edges', 0.34);
    expect(bakerLast(start)).toBe(0);
    const run = withOutcome(start, { status: 'solved', solution: explained.solution, explanation: explained });
    const baker = explained.baker!;
    expect(run.lambda).toBe(baker.lambda);
    expect(run.layers).toBe(Math.max(...baker.layer) + 1);
    expect(bakerLast(run)).toBe(baker.lambda + 1);
    expect(shiftAt(run, 0)).toBeNull();
    expect(shiftAt(run, 1)).toBe(0);
    expect(shiftAt(run, baker.lambda + 1)).toBeNull();
    const best = bestShift(run)!;
    expect(best.value).toBe(Math.max(...baker.shifts.map((x) => x.value)));
    expect(baker.shifts.findIndex((x) => x.value === best.value)).toBe(best.shift);
    expect(withOutcome(start, { status: 'failed', name: 'Error', message: 'no' }).failure).toBe('no');
  });
});
