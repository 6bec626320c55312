// Bounded solves in wasm: a wheel (a third of its quads meet at the centre, whose
// vertex term grows as 2^quads) is answered or refused at once, never "out of
// memory"; and every solve calls progress often enough to cancel it within 100 ms.
import { beforeAll, describe, expect, it } from 'vitest';
import { CancelledError, type Hodt, LimitError, loadHodt, type ObjectiveId, type Terrain } from '../../web/src/index.js';
import { hills } from './randomPoints.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

// A centre and n - 1 points on a circle, heights alternating up and down.
function wheel(n: number): Float64Array {
  const xyz = [0, 0, 0];
  for (let i = 0; i < n - 1; ++i) {
    const a = (2 * Math.PI * i) / (n - 1);
    xyz.push(Math.cos(a), Math.sin(a), i % 2 ? 1 : -1);
  }
  return Float64Array.from(xyz);
}

// CPU milliseconds of this process (vitest runs each file in its own): the work
// done between two progress calls, whatever else the machine runs.
const cpuMs = () => {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
};

// The longest stretch of work without a progress call, start and end included.
function longestGap(t: Terrain, objective: ObjectiveId, method: 'exact' | 'approx' | 'auto'): number {
  let last = cpuMs();
  let gap = 0;
  try {
    t.solve(objective, {
      method,
      progress: () => {
        const now = cpuMs();
        gap = Math.max(gap, now - last);
        last = now;
      },
    });
  } catch (e) {
    if (!(e instanceof LimitError)) throw e;
  }
  return Math.max(gap, cpuMs() - last);
}

describe('wheels', () => {
  it.each([57, 87, 150])('%i points: exact refuses at once, naming the centre; auto and approx answer with a bound', (n) => {
    using t = hodt.terrain(wheel(n));
    const start = cpuMs();
    for (const objective of ['min-mixed-vertices', 'minmax-degree'] as const) {
      expect(() => t.solve(objective, { method: 'exact' })).toThrow(LimitError);
      expect(() => t.solve(objective, { method: 'exact' })).toThrow(/^exact: the vertex at \(0, 0\) has \d+ flippable quads .*: its term would need 2\^\d+ entries; the exact limit is 2\^20/);
      for (const method of ['auto', 'approx'] as const) {
        const s = t.solve(objective, { method });
        expect(s.method).toBe('approx');
        expect(s.value).toBe(t.evaluate(s.choice)[objective]);
        if (!s.optimal) {
          expect(s.bound).not.toBeNull();
          expect(s.bound!).toBeLessThanOrEqual(s.value);
        }
      }
    }
    expect(cpuMs() - start).toBeLessThan(5000);
  });
});

describe('progress', () => {
  it('comes at least every 100 ms of work, in every solve', () => {
    using grid = hodt.terrain(hills(160, 5));
    using w = hodt.terrain(wheel(57));
    for (const t of [grid, w])
      for (const info of hodt.objectives) {
        const hard = ['max-convex-edges', 'min-mixed-vertices', 'minmax-degree'].includes(info.id);
        for (const method of hard ? (['exact', 'approx', 'auto'] as const) : (['auto'] as const)) {
          expect(longestGap(t, info.id as ObjectiveId, method), `${info.id}, ${method}`).toBeLessThan(100);
        }
      }
  });
  it('returning false stops the run at once', () => {
    using grid = hodt.terrain(hills(160, 5));
    for (const objective of ['max-convex-edges', 'min-mixed-vertices'] as const) {
      const start = cpuMs();
      let asked = -1;
      expect(() =>
        grid.solve(objective, {
          method: 'approx',
          progress: () => {
            if (cpuMs() - start < 30) return true;
            asked = cpuMs();
            return false;
          },
        }),
      ).toThrow(CancelledError);
      expect(asked).toBeGreaterThanOrEqual(0);
      expect(cpuMs() - asked).toBeLessThan(20);
    }
  });
});
