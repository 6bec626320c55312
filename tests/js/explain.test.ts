// Terrain.explain: the core's own structures, typed, copied out of the heap, and
// consistent with what solve() and evaluate() say of the same terrain.
import { beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, InputError, loadHodt } from '../../web/src/index.js';
import { randomPoints } from './randomPoints.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

/** A jittered grid: many adjacent quads, so searches build clauses between them. */
function jitteredGrid(w: number, h: number, seed: number): Float64Array {
  const r = randomPoints(w * h, seed);
  const p = new Float64Array(3 * w * h);
  for (let j = 0; j < h; j++)
    for (let i = 0; i < w; i++) {
      const k = j * w + i;
      p.set([i + 0.6 * (r[3 * k]! - 0.5), j + 0.6 * (r[3 * k + 1]! - 0.5), r[3 * k + 2]!], 3 * k);
    }
  return p;
}

describe('explain', () => {
  it('gives every test of the bottleneck search with its clauses and components', () => {
    let conflicts = 0;
    for (let seed = 1; seed <= 6; seed++) {
      const t = hodt.terrain(jitteredGrid(8, 7, seed));
      for (const id of ['minmax-edge-area-ratio', 'minmax-vertex-normal-angle'] as const) {
        const e = t.explain(id);
        const s = t.solve(id, { trace: true });
        expect(e.solution.value).toBe(s.value);
        expect(Array.from(e.solution.choice)).toEqual(Array.from(s.choice));
        const search = e.search!;
        expect(search.candidates).toBeInstanceOf(Float64Array);
        expect(search.tests.map((x) => x.threshold)).toEqual(s.trace.map((x) => x.threshold));
        for (const test of search.tests) {
          expect(test.clauses).toBeInstanceOf(Uint32Array);
          expect(test.component).toBeInstanceOf(Int32Array);
          if (test.immediateNo) continue;
          expect(test.component.length).toBe(2 * t.numQuads);
          if (test.satisfiable) {
            // The 2-SAT solution is a triangulation within the threshold.
            expect(t.evaluate(test.assignment)[id]).toBeLessThanOrEqual(test.threshold);
          } else {
            expect(test.conflicts.length).toBeGreaterThan(0);
            conflicts += test.conflicts.length;
            for (const q of test.conflicts) expect(test.component[2 * q]).toBe(test.component[2 * q + 1]);
          }
        }
      }
      t.dispose();
    }
    expect(conflicts).toBeGreaterThan(0);
  });

  it("gives Baker's layers and shifts in the objective's units", () => {
    const t = hodt.terrain(jitteredGrid(9, 8, 3));
    for (const id of ['max-convex-edges', 'min-mixed-vertices'] as const) {
      const e = t.explain(id, { method: 'approx', epsilon: 0.34 });
      const b = e.baker!;
      expect(b.layer.length).toBe(t.numQuads);
      expect(b.shifts.length).toBe(b.lambda);
      const exact = t.solve(id, { method: 'exact' }).value;
      for (const shift of b.shifts) {
        expect(t.evaluate(shift.choice)[id]).toBe(shift.value);
        if (id === 'max-convex-edges') expect(shift.bound).toBeGreaterThanOrEqual(exact);
        else expect(shift.bound).toBeLessThanOrEqual(exact);
      }
      expect(e.solution.bound).toBe(id === 'max-convex-edges' ? Math.min(...b.shifts.map((x) => x.bound)) : Math.max(...b.shifts.map((x) => x.bound)));
    }
    t.dispose();
  });

  it('gives the regions of the order, whose counts multiply to the number of triangulations', () => {
    const t = hodt.terrain(randomPoints(12, 5));
    const one = t.explain('min-local-minima').regions!;
    expect(Array.from(one.triangulations).filter((c) => c === 2).length).toBe(t.numQuads);
    const three = t.explain('min-local-minima', { order: 3 }).regions!;
    expect(three.order).toBe(3);
    expect(three.regionOfTriangle.length * 3).toBe(three.triangles.length);
    expect(three.useful.length).toBeGreaterThanOrEqual(one.useful.length);
    // Regions merge as the order grows: never more regions at a higher order.
    expect(three.triangulations.length).toBeLessThanOrEqual(one.triangulations.length);
    t.dispose();
  });

  it('checks its options as solve does', () => {
    const t = hodt.terrain(randomPoints(20, 2));
    expect(() => t.explain('min-local-minima', { order: 0 })).toThrow(InputError);
    expect(() => t.explain('max-convex-edges', { epsilon: 2 })).toThrow(InputError);
    t.dispose();
  });
});
