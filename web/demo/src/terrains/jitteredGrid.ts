import { seededRandom } from './rng.ts';

/**
 * About n points on a square grid, each moved by up to 15% of the spacing, with
 * smooth rolling hills for heights. A nearly regular grid has many nearly
 * cocircular quads, so many flippable ones: the classic DEM case.
 */
export function jitteredGridPoints(n: number, seed: number): Float64Array {
  const random = seededRandom(seed);
  const side = Math.max(2, Math.round(Math.sqrt(n)));
  const size = 100;
  const step = size / (side - 1);
  // A few random Gaussian hills and hollows.
  const bumps = Array.from({ length: 6 }, () => ({
    x: random() * size,
    y: random() * size,
    r: 12 + random() * 25,
    h: (random() * 2 - 1) * 12,
  }));
  const height = (x: number, y: number) =>
    20 + bumps.reduce((z, b) => z + b.h * Math.exp(-((x - b.x) ** 2 + (y - b.y) ** 2) / (b.r * b.r)), 0);
  const xyz = new Float64Array(3 * side * side);
  let k = 0;
  for (let j = 0; j < side; j++) {
    for (let i = 0; i < side; i++) {
      const edgeX = i === 0 || i === side - 1;
      const edgeY = j === 0 || j === side - 1;
      const x = i * step + (edgeX ? 0 : (random() * 2 - 1) * 0.15 * step);
      const y = j * step + (edgeY ? 0 : (random() * 2 - 1) * 0.15 * step);
      xyz[k++] = x;
      xyz[k++] = y;
      xyz[k++] = height(x, y);
    }
  }
  return xyz;
}
