import type { Analysis } from './analysis.ts';

/** Slots (in a.triangles) of the two triangles of the critical pair of a min-max
 * objective: the pair whose value is the triangulation's worst. */
export function criticalTriangles(a: Analysis): number[] {
  if (!a.critical) return [];
  const key = (t: ArrayLike<number>) => Array.from(t).sort((x, y) => x - y).join(',');
  const wanted = new Set([key(a.critical.first), key(a.critical.second)]);
  const out: number[] = [];
  for (let k = 0; k < a.triangles.length / 3; k++) {
    if (wanted.has(key(a.triangles.subarray(3 * k, 3 * k + 3)))) out.push(k);
  }
  return out;
}
