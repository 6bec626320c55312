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
 * - [[x, y, z], ...] (as GeoJSON coordinates have them; more coordinates, such
 *   as a measure, are ignored; [x, y] without a height is refused);
 * - [{x, y, z}, ...];
 * - GeoJSON (GeoJsonPoints);
 * - any array of items, with accessors (TerrainOptions x, y, z).
 */
export type PointInput =
  | Float64Array
  | ArrayLike<number>
  | ReadonlyArray<readonly [number, number, number, ...number[]]>
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
    return gather(items, 'point', (item, i) => [x(item, i), y(item, i), z(item, i)]);
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
  if (first !== null && typeof first === 'object')
    return gather(list, 'point', (p, i) => {
      if (p === null || typeof p !== 'object') throw new InputError(`point ${i}: expected {x, y, z}, got ${describeValue(p)}`);
      const { x, y, z } = p as Point3;
      return [x, y, z];
    });
  return Float64Array.from(list as ArrayLike<number>);
}

// x, y, z of each item, as `coordinates` reads them. Numbers pass (the core names
// non-finite ones); other types are named here rather than turned into NaN.
function gather(items: ArrayLike<unknown>, what: string, coordinates: (item: unknown, i: number) => ArrayLike<unknown>): Float64Array {
  const xyz = new Float64Array(items.length * 3);
  for (let i = 0; i < items.length; ++i) {
    const c = coordinates(items[i], i);
    for (let axis = 0; axis < 3; ++axis) {
      const v = c[axis];
      if (typeof v !== 'number') throw new InputError(`${what} ${i}: ${'xyz'[axis]} is ${describeValue(v)}, expected a number`);
      xyz[3 * i + axis] = v;
    }
  }
  return xyz;
}

function fromTriples(list: ArrayLike<unknown>, what: string): Float64Array {
  return gather(list, what, (p, i) => {
    const c = p as ArrayLike<unknown>;
    if (c == null || typeof c !== 'object' || typeof c.length !== 'number')
      throw new InputError(`${what} ${i}: expected [x, y, z], got ${describeValue(c)}`);
    if (c.length < 3) throw new InputError(`${what} ${i}: has ${c.length} coordinates, expected [x, y, z] (z is the height)`);
    return c;
  });
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
        for (const c of o.coordinates) coordinates.push(c);  // (no spread: a million arguments overflow the stack)
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
