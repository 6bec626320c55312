// The Water view's model (web/demo/src/teach/water/model.ts) against the library:
// the drainage of Delaunay and of the min-local-minima optimum, as the view draws it.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { jitteredGridPoints } from '../../web/demo/src/terrains/jitteredGrid.ts';
import { countsText, flowWidth, networkOf, startWater, withSolution, type WaterNetwork } from '../../web/demo/src/teach/water/model.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

/** Points per basin. */
function countBasins(w: WaterNetwork): number[] {
  const c = new Map<number, number>();
  for (const b of w.basin) c.set(b, (c.get(b) ?? 0) + 1);
  return [...c.values()];
}

/** What every network of n points must satisfy. */
function checkNetwork(w: WaterNetwork, n: number): void {
  const ends = new Set([...w.pits, ...w.outlets]);
  expect(w.basins).toBe(ends.size);
  for (let v = 0; v < n; v++) expect(ends.has(w.basin[v]!), `basin of ${v}`).toBe(true);
  expect(w.segments.length / 2).toBe(n - w.pits.length - w.outlets.length);
  for (let s = 0; s < w.segments.length / 2; s++) {
    expect(ends.has(w.segments[2 * s]!)).toBe(false);
    expect(w.basin[w.segments[2 * s]!]).toBe(w.basin[w.segments[2 * s + 1]!]);
  }
  // Water only gathers downstream: a segment carries more than the one before it.
  const into = new Map<number, number>();
  for (let s = 0; s < w.accumulation.length; s++) into.set(w.segments[2 * s]!, w.accumulation[s]!);
  for (let s = 0; s < w.accumulation.length; s++) {
    const next = into.get(w.segments[2 * s + 1]!);
    if (next !== undefined) expect(next).toBeGreaterThan(w.accumulation[s]!);
  }
  expect(w.maxAccumulation).toBe(n === 0 ? 0 : Math.max(...countBasins(w)));
}

describe('Water (water/model.ts)', () => {
  for (const [k, size, seed, fewer] of [[1, 100, 3, false], [1, 100, 8, false], [2, 100, 5, false], [3, 100, 5, false], [1, 200, 21, true], [2, 200, 21, true]] as const) {
    test(`order ${k}, ${size} points, seed ${seed}: the optimum for the fewest local minima has no more pits than Delaunay`, () => {
      const points = jitteredGridPoints(size, seed);
      using terrain = hodt.terrain(points);
      const count = points.length / 3;
      const start = startWater(terrain, k, 'min-local-minima');
      checkNetwork(start.delaunay, count);
      const library = terrain.drainage();
      expect([...start.delaunay.pits]).toEqual([...library.pits]);
      expect([...start.delaunay.basin]).toEqual([...library.basin]);
      const solution = terrain.solve('min-local-minima', k > 1 ? { order: k } : {});
      const s = withSolution(start, { status: 'solved', solution }, terrain);
      const optimum = s.optimum!;
      checkNetwork(optimum, count);
      expect(optimum.pits.length).toBeLessThanOrEqual(start.delaunay.pits.length);
      // On this terrain Delaunay has artificial pits: removing them merges basins.
      if (fewer) {
        expect(optimum.pits.length).toBeLessThan(start.delaunay.pits.length);
        expect(optimum.basins).toBeLessThan(start.delaunay.basins);
      }
      expect([...optimum.outlets]).toEqual([...terrain.drainage(solution.triangles).outlets]);
      const words = (x: WaterNetwork) => `${x.pits.length} pit${x.pits.length === 1 ? '' : 's'}, ${x.basins} basin${x.basins === 1 ? '' : 's'}`;
      expect(countsText(s)).toBe(`Delaunay: ${words(start.delaunay)}; optimum (order ${k}): ${words(optimum)}`);
    });
  }

  test('a failed solve keeps Delaunay and says why', () => {
    using terrain = hodt.terrain(jitteredGridPoints(30, 2));
    const s = withSolution(startWater(terrain, 1, 'min-local-minima'), { status: 'failed', name: 'Error', message: 'boom' }, terrain);
    expect(s.optimum).toBeNull();
    expect(countsText(s)).toMatch(/optimum \(order 1\): not solved \(boom\)$/);
  });

  test('flow width grows with log(accumulation) from 1 to the widest', () => {
    expect(flowWidth(1, 100)).toBe(1);
    expect(flowWidth(100, 100)).toBeCloseTo(6);
    expect(flowWidth(10, 100)).toBeCloseTo(3.5);
    expect(flowWidth(1, 1)).toBe(1);
  });
});
