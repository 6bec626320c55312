import type { Analysis } from './analysis.ts';

/** Height of the triangulated surface at (x, y): linear inside the triangle that
 * contains it, else (outside the hull) the height of the nearest point. */
export function heightAt(a: Analysis, x: number, y: number): number {
  const { points: p, triangles: t } = a;
  for (let k = 0; k < t.length; k += 3) {
    const i = 3 * t[k]!, j = 3 * t[k + 1]!, l = 3 * t[k + 2]!;
    const x0 = p[i]!, y0 = p[i + 1]!, x1 = p[j]!, y1 = p[j + 1]!, x2 = p[l]!, y2 = p[l + 1]!;
    const d = (y1 - y2) * (x0 - x2) + (x2 - x1) * (y0 - y2);
    if (d === 0) continue;
    const u = ((y1 - y2) * (x - x2) + (x2 - x1) * (y - y2)) / d;
    const v = ((y2 - y0) * (x - x2) + (x0 - x2) * (y - y2)) / d;
    const w = 1 - u - v;
    if (u >= 0 && v >= 0 && w >= 0) return u * p[i + 2]! + v * p[j + 2]! + w * p[l + 2]!;
  }
  let best = 0;
  let bestD = Infinity;
  for (let i = 0; i < p.length; i += 3) {
    const d = (p[i]! - x) ** 2 + (p[i + 1]! - y) ** 2;
    if (d < bestD) {
      bestD = d;
      best = p[i + 2]!;
    }
  }
  return best;
}
