// Seeded uniform points in the unit cube, x, y, z per point (the same on every run).
export function randomPoints(n: number, seed: number): Float64Array {
  let s = seed;
  const r = () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
  return Float64Array.from({ length: 3 * n }, r);
}
