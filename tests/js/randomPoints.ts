// Seeded uniform points in the unit cube, x, y, z per point (the same on every run).
export function randomPoints(n: number, seed: number): Float64Array {
  let s = seed;
  const r = () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
  return Float64Array.from({ length: 3 * n }, r);
}

// A smooth hilly terrain on jittered grid points (many flippable quads).
export function hills(side: number, seed: number): Float64Array {
  let s = seed;
  const r = () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
  const xyz: number[] = [];
  for (let j = 0; j < side; ++j)
    for (let i = 0; i < side; ++i) {
      const x = i + 0.7 * (r() - 0.5), y = j + 0.7 * (r() - 0.5);
      xyz.push(x, y, Math.sin(x / 5) * Math.cos(y / 7) * 3 + 0.2 * r());
    }
  return Float64Array.from(xyz);
}
