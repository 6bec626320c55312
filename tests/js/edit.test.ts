// Live edits through the TypeScript API against the real wasm module: after each
// edit the terrain equals one built from its points; bad edits throw and change
// nothing.
import { beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, InputError, loadHodt, type Terrain } from '../../web/src/index.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

function rng(seed: number) {
  let s = seed;
  return () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
}

const triangleSet = (triangles: Uint32Array) => {
  const out: string[] = [];
  for (let t = 0; t < triangles.length; t += 3) {
    const v = [triangles[t]!, triangles[t + 1]!, triangles[t + 2]!];
    const k = v.indexOf(Math.min(...v));
    out.push([v[k], v[(k + 1) % 3], v[(k + 2) % 3]].join(','));
  }
  return out.sort();
};

function expectSameAsFresh(t: Terrain) {
  const fresh = hodt.terrain(t.points);
  expect(t.numInputPoints).toBe(fresh.numInputPoints);
  expect(triangleSet(t.delaunay().triangles)).toEqual(triangleSet(fresh.delaunay().triangles));
  expect(t.numQuads).toBe(fresh.numQuads);
  for (const o of ['min-local-minima', 'minmax-edge-area-ratio', 'max-convex-edges'] as const)
    expect(t.solve(o).value).toBe(fresh.solve(o).value);
  expect(t.delaunayValues()).toEqual(fresh.delaunayValues());
  fresh.dispose();
}

describe('live edits', () => {
  it('move, add and remove points: the terrain equals a fresh one', () => {
    const r = rng(5);
    const t = hodt.terrain(Float64Array.from({ length: 300 }, r));
    for (let i = 0; i < 60; ++i) {
      const k = Math.floor(r() * t.numInputPoints);
      const [x, y, z] = [r(), r(), r()];
      if (i % 3 === 0) t.movePoint(k, x, y, z);
      else if (i % 3 === 1) expect(t.addPoint(x, y, z)).toBe(t.numInputPoints - 1);
      else t.removePoint(k);
      expectSameAsFresh(t);
    }
    const p = t.points;
    t.movePoint(3, 0.5, 0.25, 7);
    expect(Array.from(t.points.subarray(9, 12))).toEqual([0.5, 0.25, 7]);
    t.removePoint(0);
    expect(t.points.length).toBe(p.length - 3);
    expect(Array.from(t.points.subarray(6, 9))).toEqual([0.5, 0.25, 7]);  // point 3 is now point 2
    t.dispose();
  });

  it('bad edits name what is wrong and change nothing', () => {
    const grid = new Float64Array(3 * 16);
    for (let i = 0; i < 16; ++i) grid.set([i % 4, Math.floor(i / 4), 0], 3 * i);
    const t = hodt.terrain(grid);
    const before = t.delaunay().triangles;
    expect(() => t.addPoint(1, 1, 0)).toThrow(new InputError('point 16 has the same (x, y) = (1, 1) as point 5'));
    expect(() => t.movePoint(0, 2, 2, 0)).toThrow(/point 0 cannot move to \(2, 2\): point 10 is there/);
    expect(() => t.movePoint(16, 0.5, 0.5, 0)).toThrow(/point 16 is out of range \(16 points\)/);
    expect(() => t.movePoint(-1, 0.5, 0.5, 0)).toThrow(/point -1 is out of range/);
    expect(() => t.removePoint(1.5)).toThrow(/point 1.5 is out of range/);
    expect(() => t.addPoint(0.5, Number.NaN, 0)).toThrow(/point 16: y is NaN, expected a finite number/);
    expect(t.delaunay().triangles).toEqual(before);
    expect(t.numInputPoints).toBe(16);
    const three = hodt.terrain(new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0]));
    expect(() => three.removePoint(1)).toThrow(/need at least 3 distinct points, got 2/);
    expect(three.points.length).toBe(9);
    three.dispose();
    t.dispose();
  });
});
