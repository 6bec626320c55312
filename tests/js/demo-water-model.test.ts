// The Water view's model (web/demo/src/teach/water/model.ts) against the library:
// the drainage of Delaunay and of the min-local-minima optimum, as the view draws it.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { jitteredGridPoints } from '../../web/demo/src/terrains/jitteredGrid.ts';
import { countsText, networkOf, sideCounts, sidesOf, startWater, withSolution, type WaterNetwork } from '../../web/demo/src/teach/water/model.ts';
import { BASIN_COLORS, basinSlots, flowWidth, majorityBasin } from '../../web/demo/src/teach/water/waterStyle.js';

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

/** The basins' colours: every point in the slot of its Delaunay basin, one slot
 * per basin, and Delaunay basins side by side in different slots. */
function checkSlots(slots: Int32Array, delaunay: WaterNetwork, n: number): void {
  const slotOfBasin = new Map<number, number>();
  for (let v = 0; v < n; v++) {
    const r = delaunay.basin[v]!;
    expect(slots[v]).toBeGreaterThanOrEqual(0);
    expect(slots[v]).toBeLessThan(BASIN_COLORS.length);
    if (slotOfBasin.has(r)) expect(slots[v]).toBe(slotOfBasin.get(r));
    slotOfBasin.set(r, slots[v]!);
  }
  // A planar map of basins needs no more slots than there are, so neighbours differ.
  const t = delaunay.triangles;
  for (let k = 0; k < t.length; k++) {
    const a = t[k]!, b = t[k - (k % 3) + ((k % 3) + 1) % 3]!;
    if (delaunay.basin[a] !== delaunay.basin[b]) expect(slots[a], `basins of ${a} and ${b}`).not.toBe(slots[b]);
  }
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
      expect([sideCounts(s, 'delaunay'), sideCounts(s, 'optimum')]).toEqual([words(start.delaunay), words(optimum)]);
      expect(sideCounts(start, 'optimum')).toBe('solving…');
      checkSlots(s.slots, start.delaunay, count);
    });
  }

  test('a failed solve keeps Delaunay and says why', () => {
    using terrain = hodt.terrain(jitteredGridPoints(30, 2));
    const s = withSolution(startWater(terrain, 1, 'min-local-minima'), { status: 'failed', name: 'Error', message: 'boom' }, terrain);
    expect(s.optimum).toBeNull();
    expect(countsText(s)).toMatch(/optimum \(order 1\): not solved \(boom\)$/);
  });

  test('a basin of the optimum takes the colour of the Delaunay basin its pit or outlet lies in', () => {
    const points = jitteredGridPoints(200, 21);
    using terrain = hodt.terrain(points);
    const start = startWater(terrain, 2, 'min-local-minima');
    const s = withSolution(start, { status: 'solved', solution: terrain.solve('min-local-minima', { order: 2 }) }, terrain);
    const d = start.delaunay, o = s.optimum!;
    // A pit the optimum removed: its water now ends in another Delaunay basin, and
    // its points show in that basin's colour, not their own.
    const gone = [...d.pits].filter((p) => !o.pits.includes(p));
    expect(gone.length).toBeGreaterThan(0);
    for (const p of gone) {
      expect(d.basin[o.basin[p]!]).not.toBe(p);
      expect(s.slots[o.basin[p]!]).not.toBe(s.slots[p]);
    }
    // A triangle of the optimum is coloured by the basin of two of its corners.
    for (let t = 0; t < o.triangles.length / 3; t++) {
      const r = majorityBasin(o.triangles, o.basin, t);
      const corners = [0, 1, 2].map((j) => o.basin[o.triangles[3 * t + j]!]!);
      expect(r === -1 ? new Set(corners).size : corners.filter((c) => c === r).length).toBeGreaterThanOrEqual(r === -1 ? 3 : 2);
    }
    expect(sidesOf('both')).toEqual(['delaunay', 'optimum']);
    expect(sidesOf('optimum')).toEqual(['optimum']);
  });

  test('colour slots: more basins than slots still colour every basin', () => {
    // A fan of 12 triangles around a centre, each rim point its own basin (rim
    // neighbours differ in slot), the centre in a basin of its own.
    const n = 13, triangles: number[] = [];
    for (let i = 0; i < 12; i++) triangles.push(0, 1 + i, 1 + ((i + 1) % 12));
    const slots = basinSlots(triangles, Array.from({ length: n }, (_, v) => v), BASIN_COLORS.length);
    for (let i = 0; i < 12; i++) expect(slots[1 + i]).not.toBe(slots[1 + ((i + 1) % 12)]);
    for (let i = 1; i < n; i++) expect(slots[i]).not.toBe(slots[0]);
    expect(new Set(slots).size).toBeLessThanOrEqual(BASIN_COLORS.length);
    expect([...basinSlots(triangles, [-1, ...Array.from({ length: 12 }, () => 5)], 8)]).toEqual([-1, ...Array(12).fill(0)]);
  });

  test('flow width grows with log(accumulation) from 1 to the widest', () => {
    expect(flowWidth(1, 100)).toBe(1);
    expect(flowWidth(100, 100)).toBeCloseTo(6);
    expect(flowWidth(10, 100)).toBeCloseTo(3.5);
    expect(flowWidth(1, 1)).toBe(1);
  });
});
