// The TypeScript API against the real wasm module in Node.
import { beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, InputError, LimitError, loadHodt, OBJECTIVE_IDS } from '../../web/src/index.js';
import { randomPoints } from './randomPoints.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

describe('terrain handles', () => {
  it('builds a terrain and reads its structure as typed arrays', () => {
    const t = hodt.terrain(randomPoints(40, 1));
    expect(t.numPoints).toBe(40);
    const d = t.delaunay();
    expect(d.triangles).toBeInstanceOf(Uint32Array);
    expect(d.halfedges).toBeInstanceOf(Int32Array);
    expect(d.triangles.length).toBe(3 * (2 * 40 - d.hull.length - 2));
    for (let e = 0; e < d.halfedges.length; ++e) {
      const f = d.halfedges[e]!;
      if (f >= 0) expect(d.halfedges[f]).toBe(e);
    }
    expect(t.quads.length).toBe(4 * t.numQuads);
    t.dispose();
    expect(t.disposed).toBe(true);
    t.dispose(); // idempotent
    expect(() => t.numQuads).toThrow(InputError);
  });

  it('supports Symbol.dispose (using)', () => {
    const t = hodt.terrain(randomPoints(10, 2));
    t[Symbol.dispose]();
    expect(t.disposed).toBe(true);
  });

  it('accepts {x, y, z} objects', () => {
    const t = hodt.terrain([{ x: 0, y: 0, z: 1 }, { x: 1, y: 0, z: 2 }, { x: 0, y: 1, z: 3 }]);
    expect(t.delaunay().triangles.length).toBe(3);
    t.dispose();
  });

  it('drops duplicates on request and reports triangles in input indices', () => {
    const xyz = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 9, 1, 1, 1];
    expect(() => hodt.terrain(xyz)).toThrow(/point 1 and point 3 have the same \(x, y\) = \(1, 0\)/);
    const t = hodt.terrain(xyz, { dedupe: 'first' });
    expect(t.numPoints).toBe(4);
    expect(Array.from(t.vertexIndex)).toEqual([0, 1, 2, 4]);
    const used = new Set(t.delaunay().triangles);
    expect(used.has(3)).toBe(false);
    expect(used.has(4)).toBe(true);
    t.dispose();
  });

  it('results are copies: they survive wasm memory growth', () => {
    const before0 = hodt.memoryBytes;
    const t = hodt.terrain(randomPoints(30, 3));
    const before = t.delaunay().triangles;
    const copy = Array.from(before);
    const big = hodt.terrain(randomPoints(200_000, 4)); // grows the heap
    expect(hodt.memoryBytes).toBeGreaterThan(before0);
    expect(before.length).toBe(copy.length);
    expect(Array.from(before)).toEqual(copy);
    big.dispose();
    t.dispose();
  });
});

describe('errors are typed and carry the core message', () => {
  it('InputError for NaN, naming index and coordinate', () => {
    const err = (() => {
      try {
        hodt.terrain([0, 0, 0, 1, 0, 0, 0, NaN, 0]);
      } catch (e) {
        return e;
      }
    })();
    expect(err).toBeInstanceOf(InputError);
    expect((err as Error).message).toBe('point 2: y is NaN, expected a finite number');
  });
  it('LimitError for brute force on many quads', () => {
    const t = hodt.terrain(randomPoints(400, 5));
    expect(() => t.solve('min-local-minima', { method: 'brute-force' })).toThrow(LimitError);
    t.dispose();
  });
  it('InputError for a wrong choice length', () => {
    const t = hodt.terrain(randomPoints(30, 6));
    expect(() => t.evaluate(new Uint8Array(t.numQuads + 1))).toThrow(/choice has \d+ entries, expected one per quad/);
    t.dispose();
  });
  it('InputError for a bad file, naming the line', () => {
    expect(() => hodt.readPoints('0 0 0\n1 x 1\n', 'f.txt')).toThrow(/f\.txt: line 2: y is 'x', not a number/);
  });
});

describe('evaluation and brute force', () => {
  it('evaluate(choice) equals the brute-force value of the returned choice', () => {
    const t = hodt.terrain(randomPoints(16, 7));
    for (const id of OBJECTIVE_IDS) {
      const s = t.solve(id, { method: 'brute-force' });
      expect(t.evaluate(s.choice)[id]).toBe(s.value);
      expect(s.delaunayValue).toBe(t.delaunayValues()[id]);
      expect(s.optimal).toBe(true);
      const better = s.sense === 'min' ? s.value <= s.delaunayValue : s.value >= s.delaunayValue;
      expect(better).toBe(true);
    }
    t.dispose();
  });
  it('enumerateAll lists all 2^m triangulations', () => {
    const t = hodt.terrain(randomPoints(14, 8));
    const all = t.enumerateAll();
    expect(all.length).toBe(13 * 2 ** t.numQuads);
    const k = OBJECTIVE_IDS.indexOf('min-total-edge-length');
    let best = Infinity;
    for (let c = 0; c < 2 ** t.numQuads; ++c) best = Math.min(best, all[c * 13 + k]!);
    expect(t.solve('min-total-edge-length', { method: 'brute-force' }).value).toBe(best);
    t.dispose();
  });
  it('a singly-flippable user triangulation', () => {
    // Square with a centre: 4 triangles, no flippable edge possible (not convex).
    const pts = [0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 1];
    const t = hodt.fromTriangulation(pts, [0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4], []);
    expect(t.isDelaunay).toBe(false);
    expect(t.numQuads).toBe(0);
    expect(() => hodt.fromTriangulation(pts, [0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4], [0, 4])).toThrow(/not strictly convex/);
    t.dispose();
  });
});

describe('error names survive minification', () => {
  it('are spelled out, not taken from the class name', async () => {
    const { HodtError, InputError, LimitError, CancelledError, InternalError } = await import('../../web/src/errors.js');
    expect(new HodtError('x').name).toBe('HodtError');
    expect(new InputError('x').name).toBe('InputError');
    expect(new LimitError('x').name).toBe('LimitError');
    expect(new InternalError('x').name).toBe('InternalError');
    expect(new CancelledError().name).toBe('AbortError');
    expect(new CancelledError().message).toBe('cancelled');
    expect(new InputError('x')).toBeInstanceOf(HodtError);
  });
});

describe('any triangulation given by triangles', () => {
  it('evaluates and measures a higher order result, and rejects a non-triangulation', () => {
    const t = hodt.terrain(randomPoints(40, 11));
    const best = t.solve('min-local-minima', { order: 2 });
    const values = t.evaluateTriangles(best.triangles);
    expect(values['min-local-minima']).toBe(best.value);
    const m = t.measuresOfTriangles(best.triangles);
    expect(m.degree.length).toBe(40);
    expect(m.edgeShape.length).toBe(best.triangles.length);
    // The Delaunay triangles give the Delaunay values.
    expect(t.evaluateTriangles(t.delaunay().triangles)).toEqual(t.delaunayValues());
    expect(() => t.evaluateTriangles(best.triangles.subarray(3))).toThrow(/triangles: /);
    t.dispose();
  });
});
