import { describeValue, InputError } from './errors.js';

/** One point of a terrain: z is the height. */
export interface Point3 {
  x: number;
  y: number;
  z: number;
}

/** A GeoJSON geometry or feature holding points with a height: Point,
 * MultiPoint, a Feature of one, or a FeatureCollection of them (coordinates
 * [x, y, z], as read: no projection). */
export interface GeoJsonPoints {
  type: 'Point' | 'MultiPoint' | 'Feature' | 'FeatureCollection';
  [key: string]: unknown;
}

/**
 * Points, in any of these forms:
 * - x, y, z, x, y, z, ... (a Float64Array is used as is, other arrays of numbers
 *   are converted);
 * - [[x, y, z], ...] (as d3-delaunay and GeoJSON coordinates have them);
 * - [{x, y, z}, ...];
 * - GeoJSON (GeoJsonPoints);
 * - any array of items, with accessors (TerrainOptions x, y, z).
 */
export type PointInput =
  | Float64Array
  | ArrayLike<number>
  | ReadonlyArray<readonly [number, number, number] | readonly number[]>
  | ReadonlyArray<Point3>
  | GeoJsonPoints;

/** Reads a coordinate of an item (as Delaunator.from's getX and getY). */
export type Accessor<T = any> = (item: T, index: number) => number; // eslint-disable-line @typescript-eslint/no-explicit-any

export interface Accessors {
  x?: Accessor;
  y?: Accessor;
  z?: Accessor;
}

/** The points as a flat Float64Array of x, y, z (a new array unless `points` is
 * a Float64Array and no accessor is given). Bad input: InputError naming the
 * point and what is wrong with it. */
export function toXyz(points: PointInput, accessors: Accessors = {}): Float64Array {
  const { x, y, z } = accessors;
  if (x || y || z) {
    if (!x || !y || !z) throw new InputError('accessors: give all three of x, y and z');
    for (const [name, f] of [['x', x], ['y', y], ['z', z]] as const)
      if (typeof f !== 'function') throw new InputError(`accessor ${name} is ${describeValue(f)}, expected a function`);
    const items = points as ArrayLike<unknown>;
    if (items == null || typeof items.length !== 'number') throw new InputError('points: expected an array of items for the accessors');
    const xyz = new Float64Array(items.length * 3);
    for (let i = 0; i < items.length; ++i) {
      xyz[3 * i] = number(x(items[i], i), i, 'x');
      xyz[3 * i + 1] = number(y(items[i], i), i, 'y');
      xyz[3 * i + 2] = number(z(items[i], i), i, 'z');
    }
    return xyz;
  }
  if (points instanceof Float64Array) return points;
  if (points !== null && typeof points === 'object' && typeof (points as GeoJsonPoints).type === 'string')
    return fromGeoJson(points as GeoJsonPoints);
  if (points == null || typeof (points as ArrayLike<unknown>).length !== 'number') {
    throw new InputError(
      'points: expected x, y, z numbers (a Float64Array), [[x, y, z], ...], [{x, y, z}, ...] or GeoJSON points',
    );
  }
  const list = points as ArrayLike<unknown>;
  const first = list[0];
  if (Array.isArray(first) || ArrayBuffer.isView(first)) return fromTriples(list, 'point');
  if (first !== null && typeof first === 'object') {
    const xyz = new Float64Array(list.length * 3);
    for (let i = 0; i < list.length; ++i) {
      const p = list[i] as Point3;
      if (p === null || typeof p !== 'object') throw new InputError(`point ${i}: expected {x, y, z}, got ${describeValue(p)}`);
      xyz[3 * i] = number(p.x, i, 'x');
      xyz[3 * i + 1] = number(p.y, i, 'y');
      xyz[3 * i + 2] = number(p.z, i, 'z');
    }
    return xyz;
  }
  return Float64Array.from(list as ArrayLike<number>);
}

// A coordinate as given: numbers pass (the core names non-finite ones), other
// types are named here rather than turned into NaN.
function number(v: unknown, i: number, axis: string): number {
  if (typeof v !== 'number') throw new InputError(`point ${i}: ${axis} is ${describeValue(v)}, expected a number`);
  return v;
}

function fromTriples(list: ArrayLike<unknown>, what: string): Float64Array {
  const xyz = new Float64Array(list.length * 3);
  for (let i = 0; i < list.length; ++i) {
    const p = list[i] as ArrayLike<unknown>;
    if (p == null || typeof p !== 'object' || typeof p.length !== 'number')
      throw new InputError(`${what} ${i}: expected [x, y, z], got ${describeValue(p)}`);
    if (p.length < 3)
      throw new InputError(`${what} ${i}: has ${p.length} coordinates, expected [x, y, z] (z is the height)`);
    xyz[3 * i] = number(p[0], i, 'x');
    xyz[3 * i + 1] = number(p[1], i, 'y');
    xyz[3 * i + 2] = number(p[2], i, 'z');
  }
  return xyz;
}

// Point and MultiPoint coordinates, in document order.
function fromGeoJson(g: GeoJsonPoints): Float64Array {
  const coordinates: unknown[] = [];
  const visit = (node: unknown, where: string): void => {
    const o = node as { type?: unknown; coordinates?: unknown; geometry?: unknown; features?: unknown };
    if (o === null || typeof o !== 'object') throw new InputError(`GeoJSON ${where}: expected an object, got ${describeValue(node)}`);
    switch (o.type) {
      case 'FeatureCollection':
        if (!Array.isArray(o.features)) throw new InputError(`GeoJSON ${where}: a FeatureCollection without features`);
        o.features.forEach((f, i) => visit(f, `feature ${i}`));
        return;
      case 'Feature':
        if (o.geometry === null) return;  // (GeoJSON allows unlocated features)
        return visit(o.geometry, where);
      case 'Point':
        coordinates.push(o.coordinates);
        return;
      case 'MultiPoint':
        if (!Array.isArray(o.coordinates)) throw new InputError(`GeoJSON ${where}: MultiPoint coordinates are not an array`);
        coordinates.push(...o.coordinates);
        return;
      default:
        throw new InputError(
          `GeoJSON ${where}: geometry type ${describeValue(o.type)}, expected Point or MultiPoint (the points of a terrain)`,
        );
    }
  };
  visit(g, 'input');
  return fromTriples(coordinates, 'GeoJSON point');
}
