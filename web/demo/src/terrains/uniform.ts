import { seededRandom } from './rng.ts';

/** n points uniformly at random in a 100 x 100 square, each with a random height
 * in [0, 12]: a rough terrain with many pits and peaks, good for the extrema
 * objectives. Corners are included so the outline is the square. */
export function uniformPoints(n: number, seed: number): Float64Array {
  const random = seededRandom(seed);
  const size = 100;
  const xyz = new Float64Array(3 * n);
  const corners = [0, 0, size, 0, size, size, 0, size];
  for (let i = 0; i < n; i++) {
    const x = i < 4 ? corners[2 * i]! : random() * size;
    const y = i < 4 ? corners[2 * i + 1]! : random() * size;
    xyz[3 * i] = x;
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = random() * 12;
  }
  return xyz;
}
