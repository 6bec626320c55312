// Calls on a terrain from inside the progress callback of its own solve(): the core
// is using the terrain, so changing it, freeing it or starting another solve is
// refused with BusyError (never a use after free or a change under the solver);
// reads are allowed, and other terrains are free to use.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { BusyError, type Hodt, InputError, loadHodt, type Terrain } from '../../web/src/index.js';
import { randomPoints } from './randomPoints.js';

let hodt: Hodt;
let other: Terrain;

beforeAll(async () => {
  hodt = await loadHodt();
  other = hodt.terrain(randomPoints(100, 2));
});
afterAll(() => other.dispose());

// A solve that calls its progress callback (the exact DP reports at its start).
const solveWith = (t: Terrain, progress: () => void) => t.solve('max-convex-edges', { method: 'exact', progress });

const busy = (method: string) => `terrain is busy: ${method} called from inside a progress callback of solve()`;

describe('changing or freeing a terrain from its own progress callback', () => {
  const calls: [string, (t: Terrain) => unknown][] = [
    ['dispose', (t) => t.dispose()],
    ['addPoint', (t) => t.addPoint(0.5, 0.5, 1)],
    ['movePoint', (t) => t.movePoint(3, 0.25, 0.75, 1)],
    ['removePoint', (t) => t.removePoint(3)],
    ['solve', (t) => t.solve('min-local-minima')],
  ];
  it.each(calls)('%s throws BusyError, and the solve stops with it', (method, call) => {
    const t = hodt.terrain(randomPoints(400, 7));
    const quads = t.numQuads;
    let error: unknown;
    try {
      solveWith(t, () => void call(t));
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(BusyError);
    expect(error).toBeInstanceOf(InputError);
    expect((error as Error).message).toBe(busy(method));
    // Nothing changed: the terrain is whole and usable, and can be freed now.
    expect(t.disposed).toBe(false);
    expect(t.numInputPoints).toBe(400);
    expect(t.numQuads).toBe(quads);
    expect(solveWith(t, () => {}).optimal).toBe(true);
    call(t);
    if (method !== 'dispose') t.dispose();
    expect(t.disposed).toBe(true);
  });

  it('a callback that catches BusyError lets the solve finish normally', () => {
    using t = hodt.terrain(randomPoints(400, 7));
    const caught: unknown[] = [];
    const s = solveWith(t, () => {
      try {
        t.addPoint(0.5, 0.5, 1);
      } catch (e) {
        caught.push(e);
      }
    });
    expect(caught.length).toBeGreaterThan(0);
    expect(caught[0]).toBeInstanceOf(BusyError);
    expect(s.value).toBe(t.solve('max-convex-edges', { method: 'exact' }).value);
    expect(t.numInputPoints).toBe(400);
  });
});

describe('what a progress callback may do', () => {
  it('read the terrain it is solving', () => {
    using t = hodt.terrain(randomPoints(400, 7));
    const seen: number[] = [];
    const s = solveWith(t, () => {
      seen.push(t.numQuads, t.delaunay().triangles.length, t.evaluate()[0]!, t.points.length);
    });
    expect(seen.length).toBeGreaterThan(0);
    expect(s.optimal).toBe(true);
  });
  it('use another terrain, even solve it', () => {
    using t = hodt.terrain(randomPoints(400, 7));
    const values: number[] = [];
    const s = solveWith(t, () => void values.push(other.solve('min-local-minima').value));
    expect(values.length).toBeGreaterThan(0);
    expect(s.optimal).toBe(true);
    other.addPoint(0.123, 0.456, 1);  // and the other one is not busy
  });
});

describe('solves nested in another solve of the same function', () => {
  // Every bound function called inside a call of itself: embind once shared each
  // function's argument arrays between calls, so the outer call freed the inner
  // call's arguments twice and the heap broke a few solves later.
  it('every objective, with every objective solved inside its progress callback, answers as alone', () => {
    const ids = hodt.objectives.map((o) => o.id);
    const inner = (seed: number) => randomPoints(150, 11 + seed);
    const alone = new Map<string, number>();
    for (let c = 1; c <= 3; ++c) for (const id of ids) alone.set(`${c} ${id}`, hodt.terrain(inner(c)).solve(id).value);
    for (const outerId of ids) {
      using outer = hodt.terrain(randomPoints(300, 7));
      const expected = outer.solve(outerId).value;
      let calls = 0;
      const s = outer.solve(outerId, {
        progress: () => {
          if (++calls > 3) return;
          for (const id of ids) {
            using t = hodt.terrain(inner(calls));
            expect(t.solve(id, { progress: () => {} }).value).toBe(alone.get(`${calls} ${id}`));
          }
        },
      });
      expect(s.value).toBe(expected);
    }
  }, 120_000);
});

describe('after a trap', () => {
  it('every later call on the module throws InternalError saying so; delete is quiet', async () => {
    const { stopAfterTrap } = await import('../../web/src/trap.js');
    const { InternalError } = await import('../../web/src/errors.js');
    class TerrainHandle {
      solve() {
        throw new WebAssembly.RuntimeError('memory access out of bounds');
      }
      numPoints() {
        return 3;
      }
      delete() {
        throw new Error('must not be called after a trap');
      }
    }
    const module = { TerrainHandle, heapSize: () => 1, fromPoints: () => new TerrainHandle() } as never;
    let trapped = 0;
    stopAfterTrap(module, () => ++trapped);
    const t = (module as { fromPoints: () => TerrainHandle }).fromPoints();
    expect(t.numPoints()).toBe(3);
    expect(() => t.solve()).toThrow(/trapped \(memory access out of bounds\)/);
    expect(() => t.solve()).toThrow(InternalError);
    expect(trapped).toBe(1);
    expect(() => t.numPoints()).toThrow(/stopped after a trap/);
    expect(() => (module as { heapSize: () => number }).heapSize()).toThrow(InternalError);
    expect(t.delete()).toBeUndefined();
  });
});
