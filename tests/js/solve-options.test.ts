// Terrain.solve options: order, progress, AbortSignal, and the triangles it returns.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { CancelledError, type Hodt, HodtError, InputError, loadHodt, type Terrain } from '../../web/src/index.js';
import { randomPoints } from './randomPoints.js';

let hodt: Hodt;
let terrain: Terrain;

beforeAll(async () => {
  hodt = await loadHodt();
  terrain = hodt.terrain(randomPoints(400, 11));
});
afterAll(() => terrain.dispose());

describe('solution', () => {
  it('carries the optimised triangles, same as triangulation(choice)', () => {
    const s = terrain.solve('min-local-minima');
    expect(s.triangles).toBeInstanceOf(Uint32Array);
    expect(Array.from(s.triangles)).toEqual(Array.from(terrain.triangulation(s.choice).triangles));
    expect(s.triangles.length).toBe(terrain.delaunay().triangles.length);
    expect(s).toMatchObject({ objective: 'min-local-minima', sense: 'min', optimal: true, bound: null, details: '' });
    expect(typeof s.delaunayValue).toBe('number');
    expect(s.value).toBeLessThanOrEqual(s.delaunayValue);
  });
  it('approximations report a bound and details', () => {
    const s = terrain.solve('max-convex-edges', { method: 'approx', epsilon: 0.5 });
    expect(s.method).toBe('approx');
    expect(s.details).toMatch(/lambda/);
    expect(typeof s.localSearchImproved).toBe('boolean');
    if (!s.optimal) expect(s.bound).toBeGreaterThanOrEqual(s.value);
  });
});

describe('order', () => {
  it('accepts order 1 (the default)', () => {
    const s = terrain.solve('min-local-minima', { order: 1 });
    expect(s).toMatchObject({ order: 1, optimal: true });
    expect(s.choice.length).toBe(terrain.numQuads);
  });
  it('order 2 searches more triangulations: at least as good, with its own triangles', () => {
    using small = hodt.terrain(randomPoints(200, 3));
    const first = small.solve('min-local-minima');
    const second = small.solve('min-local-minima', { order: 2 });
    expect(second.order).toBe(2);
    expect(['exact', 'heuristic']).toContain(second.method);
    expect(second.value).toBeLessThanOrEqual(first.value);
    expect(second.choice.length).toBe(0);
    expect(second.triangles.length).toBe(first.triangles.length); // any triangulation of the points
    expect(second.delaunayValue).toBe(first.delaunayValue);
  });
  it('order 2 honours the abort signal', () => {
    using small = hodt.terrain(randomPoints(200, 3));
    expect(() => small.solve('min-local-minima', { order: 2, signal: AbortSignal.abort() })).toThrow(CancelledError);
    expect(() => small.solve('min-local-minima', { order: 2, progress: () => false })).toThrow(CancelledError);
  });
  it('refuses bad orders with a clear InputError; brute force at order k enumerates small instances only', () => {
    for (const order of [0, 17, 1.5, Number.NaN]) {
      expect(() => terrain.solve('min-local-minima', { order })).toThrow(InputError);
    }
    expect(() => terrain.solve('min-local-minima', { order: 0 })).toThrow('order is 0, expected an integer from 1 to 16');
    using small = hodt.terrain(randomPoints(200, 3));
    expect(() => small.solve('min-local-minima', { order: 2, method: 'brute-force' })).toThrow(
      /brute force at order 2 enumerates every k-OD triangulation and refuses 200 points \(at most 30\)/,
    );
    using tiny = hodt.terrain(randomPoints(10, 3));
    const bf = tiny.solve('minmax-edge-area-ratio', { order: 2, method: 'brute-force' });
    const ex = tiny.solve('minmax-edge-area-ratio', { order: 2, method: 'exact' });
    expect(bf).toMatchObject({ method: 'brute-force', optimal: true });
    expect(ex).toMatchObject({ method: 'exact', optimal: true, value: bf.value });
  });
});

describe('bad options are InputErrors naming the value', () => {
  it('method, objective, epsilon', () => {
    expect(() => terrain.solve('min-local-minima', { method: 'fast' as never })).toThrow(/unknown method 'fast'; valid methods: brute-force, exact, approx, auto/);
    expect(() => terrain.solve('nope' as never)).toThrow(/unknown objective 'nope'/);
    expect(() => terrain.solve('max-convex-edges', { epsilon: 2 })).toThrow(/epsilon is 2, expected a number in \(0, 1\)/);
    expect(() => terrain.solve('max-convex-edges', { epsilon: '0.1' as never })).toThrow(InputError);
  });
});

describe('progress', () => {
  it('is called during long runs with (done, total)', () => {
    const calls: [number, number][] = [];
    terrain.solve('max-convex-edges', { method: 'exact', progress: (done, total) => void calls.push([done, total]) });
    expect(calls.length).toBeGreaterThan(0);
    for (const [done, total] of calls) {
      expect(done).toBeGreaterThanOrEqual(0);
      expect(total).toBeGreaterThan(0);
    }
  });
  it('names each phase, whose fraction (done / total) never goes back, the same words as the CLI', () => {
    const phases = ['finding the regions', 'solving exactly', 'approximating', 'searching', 'proving a bound', 'measuring', 'solving'];
    for (const options of [{ method: 'exact' as const }, { method: 'approx' as const }, { order: 3 }]) {
      const last = new Map<string, number>();
      terrain.solve('min-mixed-vertices', {
        ...options,
        progress: (done, total, info) => {
          expect(phases).toContain(info.phase);
          expect(total).toBe(1);
          expect(info.fraction).toBe(done / total);
          expect(done).toBeGreaterThanOrEqual(last.get(info.phase) ?? 0);
          expect(done).toBeLessThanOrEqual(1);
          expect(typeof info.sized).toBe('boolean');
          if (info.secondsLeft !== null) expect(info.sized).toBe(true);
          last.set(info.phase, done);
        },
      });
      expect(last.size, JSON.stringify(options)).toBeGreaterThan(0);
      expect(last.has('solving'), JSON.stringify(options)).toBe(false); // every step of the engine named
      if (options.order === 3) expect(last.has('finding the regions')).toBe(true);
      if (options.method === 'approx') expect(last.has('approximating')).toBe(true);
    }
  });
  it('returning false cancels with CancelledError (name AbortError)', () => {
    let error: unknown;
    try {
      terrain.solve('max-convex-edges', { method: 'exact', progress: () => false });
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(CancelledError);
    expect(error).toBeInstanceOf(HodtError);
    expect((error as Error).name).toBe('AbortError');
  });
  it('an exception in the callback cancels the run and comes out unchanged', () => {
    const mine = new RangeError('mine');
    expect(() =>
      terrain.solve('max-convex-edges', {
        method: 'exact',
        progress: () => {
          throw mine;
        },
      }),
    ).toThrow(mine);
    // The terrain is still usable afterwards.
    expect(terrain.solve('max-convex-edges', { method: 'exact' }).optimal).toBe(true);
  });
});

describe('AbortSignal', () => {
  it('an aborted signal stops the run before it starts, with the reason as cause', () => {
    const reason = new Error('user left');
    let error: unknown;
    try {
      terrain.solve('min-local-minima', { signal: AbortSignal.abort(reason) });
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(CancelledError);
    expect((error as Error).name).toBe('AbortError');
    expect((error as Error).cause).toBe(reason);
  });
  it('aborting during the run (from progress) cancels at the next progress step', () => {
    const controller = new AbortController();
    let steps = 0;
    expect(() =>
      terrain.solve('max-convex-edges', {
        method: 'approx',
        signal: controller.signal,
        progress: () => {
          if (++steps === 2) controller.abort();
        },
      }),
    ).toThrow(CancelledError);
    expect(steps).toBe(2);
  });
  it('a signal that is never aborted changes nothing', () => {
    const a = terrain.solve('max-convex-edges', { method: 'exact', signal: new AbortController().signal });
    const b = terrain.solve('max-convex-edges', { method: 'exact' });
    expect(a.value).toBe(b.value);
  });
});

describe('order k with trace: the phases that ran', () => {
  it('lists the phases in the order of docs/higher-order.md, the last one deciding optimal, only when asked', async () => {
    const { readFileSync } = await import('node:fs');
    const doc = readFileSync(new URL('../../docs/higher-order.md', import.meta.url), 'utf8');
    const table = doc.slice(doc.indexOf('### The phases'), doc.indexOf('## Measuring it'));
    const names = [...table.matchAll(/^\| (?!phase \|)([^|]+?) \|/gm)].map((m) => m[1]);
    expect(names.length).toBeGreaterThan(20);
    for (const objective of ['max-convex-edges', 'minmax-vertex-normal-angle', 'min-total-edge-length'] as const) {
      const s = terrain.solve(objective, { order: 3, trace: true });
      expect(s.phases.length).toBeGreaterThan(0);
      const at = s.phases.map((p) => names.indexOf(p.phase));
      expect(at.every((i) => i >= 0)).toBe(true);
      for (let j = 1; j < at.length; j++) expect(at[j]).toBeGreaterThan(at[j - 1]);
      const last = s.phases.at(-1)!;
      expect(last.proved).toBe(s.optimal);
      expect(last.value).toBe(s.value);
      if (!s.optimal) expect(last.bound).toBe(s.bound);
      for (const p of s.phases) expect(p.ms).toBeGreaterThanOrEqual(0);
      expect(terrain.solve(objective, { order: 3 }).phases).toEqual([]);
    }
  });
});
