import { gridSize, heightAt, type HeightGrid } from './grid.ts';
import { seededRandom } from './rng.ts';

/**
 * About `count` points from a height grid by jittered grid sampling: one random
 * point per cell of an nx x ny lattice. Cells on the border keep their point on
 * the border, so the terrain has a clean rectangular outline. Deterministic for a
 * given seed. Returns x, y, z per point.
 */
export function jitteredSample(grid: HeightGrid, count: number, seed = 1): Float64Array {
  const { sizeX, sizeY } = gridSize(grid);
  const ny = Math.max(2, Math.round(Math.sqrt((count * sizeY) / sizeX)));
  const nx = Math.max(2, Math.round(count / ny));
  const random = seededRandom(seed);
  const xyz = new Float64Array(nx * ny * 3);
  let k = 0;
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const x = jitter(i, nx, sizeX, random());
      const y = jitter(j, ny, sizeY, random());
      xyz[k++] = x;
      xyz[k++] = y;
      xyz[k++] = heightAt(grid, x, y);
    }
  }
  return xyz;
}

/** Position in cell i of n along [0, size]; the first and last cells stick to the ends. */
function jitter(i: number, n: number, size: number, u: number): number {
  if (i === 0) return 0;
  if (i === n - 1) return size;
  return ((i + u) / n) * size;
}
