// solveInWorker in Node (worker_threads): the same answers as terrain.solve, and a
// long solve stopped by a timer signal, which a solve on this thread cannot see.
// It runs the built package (dist/): the worker is a JS file next to the library,
// which the sources (web/src/*.ts) do not have.
import { beforeAll, describe, expect, it } from 'vitest';
import { CancelledError, type Hodt, HodtError, InputError, LimitError, loadHodt, solveInWorker } from '../../dist/index.js';
import { hills, randomPoints } from './randomPoints.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

// 3,600 points, the fewest mixed vertices over the 6th order Delaunay
// triangulations: about 30 seconds of wasm in Node on a 2-core machine.
const longSolve = { points: hills(60, 7), objective: 'min-mixed-vertices', order: 6 } as const;

describe('solveInWorker', () => {
  it('answers as terrain.solve does, at order 1 and k, with the options passed on', async () => {
    const xyz = hills(12, 3);
    using terrain = hodt.terrain(xyz, { maxEdge: 1.5 });
    for (const [objective, options] of [
      ['min-local-minima', {}],
      ['max-convex-edges', { method: 'approx', epsilon: 0.3 }],
      ['minmax-edge-area-ratio', { trace: true }],
      ['min-local-extrema', { order: 3 }],
    ] as const) {
      const here = terrain.solve(objective, options);
      const there = await solveInWorker(xyz, objective, { ...options, terrain: { maxEdge: 1.5 } });
      const { timeMs: _a, ...same } = here;
      const { timeMs: _b, ...sameThere } = there;
      expect(sameThere, objective).toEqual(same);
    }
    expect(xyz).toEqual(hills(12, 3)); // the caller's array is not transferred away
  });

  it('reads items of your own with accessors, and keeps the first of duplicates when asked', async () => {
    const rows = Array.from({ length: 40 }, (_, i) => ({ east: i % 7, north: Math.floor(i / 7) + 0.1 * (i % 3), h: (i * 37) % 11 }));
    const best = await solveInWorker(rows, 'min-local-minima', { terrain: { x: (r) => r.east, y: (r) => r.north, z: (r) => r.h } });
    using terrain = hodt.terrain(rows, { x: (r) => r.east, y: (r) => r.north, z: (r) => r.h });
    expect(best.value).toBe(terrain.solve('min-local-minima').value);
    const twice = new Float64Array([...randomPoints(20, 5), ...randomPoints(1, 5)]);
    await expect(solveInWorker(twice, 'min-local-minima')).rejects.toThrow(InputError);
    expect((await solveInWorker(twice, 'min-local-minima', { terrain: { dedupe: 'first' } })).triangles.length).toBeGreaterThan(0);
  });

  it('rejects with the typed errors solve() throws', async () => {
    await expect(solveInWorker([0, 0, 0, 1, 0, 0, 0, Number.NaN, 0], 'min-local-minima')).rejects.toThrow(
      new InputError('point 2: y is NaN, expected a finite number'),
    );
    await expect(solveInWorker(hills(12, 3), 'max-convex-edges', { method: 'brute-force' })).rejects.toBeInstanceOf(LimitError);
    await expect(solveInWorker(hills(12, 3), 'min-local-minima', { metod: 'exact' } as object)).rejects.toThrow(
      "unknown solveInWorker option 'metod' (did you mean 'method'?)",
    );
    await expect(solveInWorker(hills(12, 3), 'min-local-minima', { wasmUrl: new URL('file:///nowhere/hodt.wasm') })).rejects.toThrow(
      /^could not load hodt\.wasm from file:\/\/\/nowhere\/hodt\.wasm: /,
    );
    await expect(solveInWorker(hills(12, 3), 'min-local-minima', { wasmUrl: 'file:///nowhere/hodt.wasm' })).rejects.toBeInstanceOf(HodtError);
    const cause = new Error('no longer needed');
    await expect(solveInWorker(hills(12, 3), 'min-local-minima', { signal: AbortSignal.abort(cause) })).rejects.toMatchObject({
      name: 'AbortError',
      cause,
    });
  });

  it('a 30-second solve is cancelled by AbortSignal.timeout(100) within a second', async () => {
    const start = performance.now();
    const error = await solveInWorker(longSolve.points, longSolve.objective, { order: longSolve.order, signal: AbortSignal.timeout(100) }).catch((e: unknown) => e);
    const elapsed = performance.now() - start;
    expect(error).toBeInstanceOf(CancelledError);
    expect((error as CancelledError).cause).toMatchObject({ name: 'TimeoutError' });
    expect(elapsed).toBeGreaterThanOrEqual(100);
    expect(elapsed).toBeLessThan(1000);
  });

  it('the same solve reports progress from the worker, and progress returning false cancels it', async () => {
    let calls = 0;
    const start = performance.now();
    const error = await solveInWorker(longSolve.points, longSolve.objective, {
      order: longSolve.order,
      progress: () => ++calls < 20,
    }).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(CancelledError);
    expect(calls).toBe(20);
    expect(performance.now() - start).toBeLessThan(10_000);
  });
});
