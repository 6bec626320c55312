import { InputError } from './errors.js';

/** One point of a terrain: z is the height. */
export interface Point3 {
  x: number;
  y: number;
  z: number;
}

/**
 * Points as x, y, z, x, y, z, ... (a Float64Array is used as is, other arrays of
 * numbers are converted) or as objects with x, y and z.
 */
export type PointInput = Float64Array | ArrayLike<number> | ReadonlyArray<Point3>;

/** The points as a flat Float64Array of x, y, z (a new array unless `points` is one). */
export function toXyz(points: PointInput): Float64Array {
  if (points instanceof Float64Array) return points;
  if (points == null || typeof points.length !== 'number') {
    throw new InputError('points: expected a Float64Array of x, y, z or an array of {x, y, z}');
  }
  const first = (points as ArrayLike<unknown>)[0];
  if (first !== null && typeof first === 'object') {
    const list = points as ReadonlyArray<Point3>;
    const xyz = new Float64Array(list.length * 3);
    for (let i = 0; i < list.length; ++i) {
      const p = list[i];
      if (p === null || typeof p !== 'object') throw new InputError(`point ${i}: expected {x, y, z}`);
      xyz[3 * i] = Number(p.x);
      xyz[3 * i + 1] = Number(p.y);
      xyz[3 * i + 2] = Number(p.z);
    }
    return xyz;
  }
  return Float64Array.from(points as ArrayLike<number>);
}
