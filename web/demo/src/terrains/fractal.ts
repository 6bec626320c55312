import type { HeightGrid } from './grid.ts';
import { seededRandom } from './rng.ts';
import { jitteredSample } from './sample.ts';

/**
 * A fractal height grid by the diamond-square algorithm: (2^levels + 1)^2 heights,
 * each level halving the random displacement by 2^-roughness. Deterministic for a
 * given seed.
 */
export function diamondSquare(levels: number, seed: number, roughness = 0.9): HeightGrid {
  const size = (1 << levels) + 1;
  const h = new Float64Array(size * size);
  const random = seededRandom(seed);
  const noise = (scale: number) => (random() * 2 - 1) * scale;
  const at = (r: number, c: number) => h[r * size + c]!;
  const set = (r: number, c: number, v: number) => (h[r * size + c] = v);
  for (const [r, c] of [[0, 0], [0, size - 1], [size - 1, 0], [size - 1, size - 1]] as const) set(r, c, noise(1));

  let scale = 1;
  for (let step = size - 1; step > 1; step >>= 1) {
    const half = step >> 1;
    // Diamond: the centre of each square is the mean of its corners plus noise.
    for (let r = half; r < size; r += step) {
      for (let c = half; c < size; c += step) {
        const mean = (at(r - half, c - half) + at(r - half, c + half) + at(r + half, c - half) + at(r + half, c + half)) / 4;
        set(r, c, mean + noise(scale));
      }
    }
    // Square: the midpoint of each edge is the mean of its (3 or 4) neighbours plus noise.
    for (let r = 0; r < size; r += half) {
      for (let c = (r / half) % 2 === 0 ? half : 0; c < size; c += step) {
        let sum = 0;
        let count = 0;
        for (const [dr, dc] of [[-half, 0], [half, 0], [0, -half], [0, half]] as const) {
          const rr = r + dr;
          const cc = c + dc;
          if (rr >= 0 && rr < size && cc >= 0 && cc < size) {
            sum += at(rr, cc);
            count++;
          }
        }
        set(r, c, sum / count + noise(scale));
      }
    }
    scale *= 2 ** -roughness;
  }
  // Heights in [0, 40] over a 100 x 100 square.
  let lo = Infinity;
  let hi = -Infinity;
  for (const v of h) {
    lo = Math.min(lo, v);
    hi = Math.max(hi, v);
  }
  for (let k = 0; k < h.length; k++) h[k] = ((h[k]! - lo) / (hi - lo || 1)) * 40;
  return { width: size, height: size, values: h, spacing: 100 / (size - 1) };
}

/** About n points sampled from a diamond-square terrain (jittered sampling). */
export function fractalPoints(n: number, seed: number): Float64Array {
  return jitteredSample(diamondSquare(7, seed), n, seed + 1);
}
