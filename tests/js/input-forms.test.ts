// What JavaScript developers bring: points as nested arrays, objects, GeoJSON or
// items with accessors; misspelt options; repeated reads of a terrain's arrays;
// terrains they forget to dispose.
import { spawnSync } from 'node:child_process';
import { beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, InputError, loadHodt } from '../../web/src/index.js';
import { randomPoints } from './randomPoints.js';

const root = new URL('../../', import.meta.url).pathname;

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

// The same terrain whatever the form: same triangles and same optimum.
function sameAsFlat(flat: Float64Array, other: Parameters<Hodt['terrain']>[0], options = {}) {
  const a = hodt.terrain(flat);
  const b = hodt.terrain(other, options);
  expect(b.points).toEqual(flat);
  expect(b.delaunay().triangles).toEqual(a.delaunay().triangles);
  expect(b.solve('min-local-minima').value).toBe(a.solve('min-local-minima').value);
  a.dispose();
  b.dispose();
}

describe('point input forms', () => {
  const flat = randomPoints(50, 11);
  const triples = Array.from({ length: 50 }, (_, i) => [flat[3 * i]!, flat[3 * i + 1]!, flat[3 * i + 2]!]);

  it('nested arrays [[x, y, z], ...], as d3-delaunay users have them', () => sameAsFlat(flat, triples));
  it('objects {x, y, z}', () => sameAsFlat(flat, triples.map(([x, y, z]) => ({ x: x!, y: y!, z: z! }))));
  it('items of your own with accessors, as Delaunator.from', () => {
    const rows = triples.map(([e, n, h], i) => ({ id: i, east: String(e), north: n, h }));
    sameAsFlat(flat, rows, { x: (r: { east: string }) => Number(r.east), y: (r: { north: number }) => r.north, z: (r: { h: number }) => r.h });
    expect(() => hodt.terrain(rows, { x: (r: { north: number }) => r.north })).toThrow(
      new InputError('accessors: give all three of x, y and z'),
    );
    expect(() => hodt.terrain(rows, { x: () => 1, y: () => 2, z: (r: { east: string }) => r.east as unknown as number })).toThrow(
      /^point 0: z is '0\.\d+', expected a number$/,
    );
  });
  it('GeoJSON: a FeatureCollection of Points, a MultiPoint, a Feature', () => {
    const features = triples.map((c, i) => ({ type: 'Feature', properties: { i }, geometry: { type: 'Point', coordinates: c } }));
    sameAsFlat(flat, { type: 'FeatureCollection', features });
    sameAsFlat(flat, { type: 'MultiPoint', coordinates: triples });
    sameAsFlat(flat, { type: 'Feature', properties: null, geometry: { type: 'MultiPoint', coordinates: triples } });
  });
  it('names what is wrong: 2D coordinates, other geometries, holes in a list', () => {
    expect(() => hodt.terrain({ type: 'MultiPoint', coordinates: [[0, 0, 1], [1, 0]] })).toThrow(
      new InputError('GeoJSON point 1: has 2 coordinates, expected [x, y, z] (z is the height)'),
    );
    expect(() => hodt.terrain({ type: 'FeatureCollection', features: [{ type: 'Feature', geometry: { type: 'LineString', coordinates: [] } }] })).toThrow(
      new InputError("GeoJSON feature 0: geometry type 'LineString', expected Point or MultiPoint (the points of a terrain)"),
    );
    expect(() => hodt.terrain([[0, 0, 0], [1, 0, 0], null as unknown as number[]])).toThrow(
      new InputError('point 2: expected [x, y, z], got null'),
    );
    expect(() => hodt.terrain([[0, 0, 0], [1, 0, 0], [0, 1, '2' as unknown as number]])).toThrow(
      new InputError("point 2: z is '2', expected a number"),
    );
    expect(() => hodt.terrain(42 as unknown as number[])).toThrow(/^points: expected x, y, z numbers/);
  });
});

describe('options are checked by name', () => {
  it('a misspelt solve option is an error that suggests the right one', () => {
    const t = hodt.terrain(randomPoints(20, 3));
    expect(() => t.solve('min-local-minima', { metod: 'exact' } as never)).toThrow(
      new InputError("unknown solve option 'metod' (did you mean 'method'?)"),
    );
    expect(() => t.solve('min-local-minima', { speed: 3 } as never)).toThrow(
      new InputError("unknown solve option 'speed' (expected 'method', 'epsilon', 'order', 'trace', 'progress', 'signal')"),
    );
    expect(() => t.solve('min-local-minima', { progress: 5 } as never)).toThrow(
      new InputError('progress is 5, expected a function'),
    );
    expect(() => t.solve('min-local-minima', 'exact' as never)).toThrow(
      new InputError("solve options are 'exact', expected an object"),
    );
    expect(t.solve('min-local-minima', { method: 'exact', order: 2 }).optimal).toBe(true);
    t.dispose();
  });
  it('terrain and loadHodt options too', async () => {
    expect(() => hodt.terrain(randomPoints(10, 1), { maxedge: 3 } as never)).toThrow(
      new InputError("unknown terrain option 'maxedge' (did you mean 'maxEdge'?)"),
    );
    await expect(loadHodt({ wasmURL: 'x' } as never)).rejects.toThrow(
      new InputError("unknown loadHodt option 'wasmURL' (did you mean 'wasmUrl'?)"),
    );
  });
});

describe('a terrain’s own arrays are read once per version', () => {
  it('the same array until the terrain changes; earlier reads keep their values', () => {
    const t = hodt.terrain(randomPoints(200, 5));
    const [points, quads, vertexIndex, quadEdges, quadOfTriangle] = [t.points, t.quads, t.vertexIndex, t.quadEdges, t.quadOfTriangle];
    expect(t.points).toBe(points);
    expect(t.quads).toBe(quads);
    expect(t.vertexIndex).toBe(vertexIndex);
    expect(t.quadEdges).toBe(quadEdges);
    expect(t.quadOfTriangle).toBe(quadOfTriangle);
    const start = performance.now();
    let sum = 0;
    for (let i = 0; i < 2000; ++i) sum += t.points[i % 600]! + t.quads.length;
    expect(sum).not.toBeNaN();
    expect(performance.now() - start).toBeLessThan(200);  // (copying each time took 650 ms on 170k points)
    const before = Array.from(points);
    t.movePoint(0, 0.5, 0.5, 9);
    expect(t.points).not.toBe(points);
    expect(Array.from(points)).toEqual(before);  // the old read is unchanged
    expect(Array.from(t.points.subarray(0, 3))).toEqual([0.5, 0.5, 9]);
    const fresh = hodt.terrain(t.points);
    expect(t.quads).not.toBe(quads);  // re-read after the edit: the same quads as a fresh build
    const quadSet = (q: Uint32Array) =>
      Array.from({ length: q.length / 4 }, (_, i) => {
        const [a, b, c, d] = q.subarray(4 * i, 4 * i + 4);
        return [Math.min(a!, b!), Math.max(a!, b!), Math.min(c!, d!), Math.max(c!, d!)].join();
      }).sort();
    expect(quadSet(t.quads)).toEqual(quadSet(fresh.quads));
    fresh.dispose();
    t.dispose();
  });
});

describe('a terrain that is never disposed', () => {
  it('is freed after garbage collection (FinalizationRegistry)', () => {
    // In a child Node with --expose-gc: 30 terrains of 100k points, dropped
    // undisposed, held about 300 MB of wasm memory if nothing freed them.
    const script = `
      const { loadHodt } = await import(${JSON.stringify(`${root}dist/index.js`)});
      const hodt = await loadHodt();
      const xyz = new Float64Array(300000).map(Math.random);
      for (let i = 0; i < 30; ++i) {
        hodt.terrain(xyz).numQuads;
        globalThis.gc();
        await new Promise((r) => setTimeout(r, 10));
      }
      console.log(hodt.memoryBytes);`;
    const r = spawnSync('node', ['--expose-gc', '--input-type=module', '-e', script], { encoding: 'utf8' });
    expect(r.status, r.stderr).toBe(0);
    expect(Number(r.stdout)).toBeLessThan(100 * 2 ** 20);
  });
});
