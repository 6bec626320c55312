// The options of hodt.terrain(): one set for the PointInput forms, one for items
// of your own with accessors typed by the item.
import type { Accessor } from './points.js';

export interface TerrainOptions<T = unknown> {
  /** Two points at the same (x, y): throw InputError (default) or keep the first. */
  dedupe?: 'error' | 'first';
  /** The domain (Terrain.maxEdge): triangles with a longer edge are not
   * measured. Default null: every triangle is measured. */
  maxEdge?: number | null;
  /** Accessors for points given as an array of items of your own, as
   * `Delaunator.from(points, getX, getY)`: all three, each (item, index) => number. */
  x?: Accessor<T>;
  y?: Accessor<T>;
  z?: Accessor<T>;
}

/** TerrainOptions for points in one of the PointInput forms: no accessors. */
export type PointOptions = Omit<TerrainOptions, 'x' | 'y' | 'z'> & { x?: undefined; y?: undefined; z?: undefined };

/** TerrainOptions for an array of items of your own: all three accessors, each
 * typed with the item type, so `(r) => r.east` knows what `r` is. */
export type AccessorOptions<T> = TerrainOptions<T> & { x: Accessor<T>; y: Accessor<T>; z: Accessor<T> };

export const TERRAIN_OPTIONS = ['dedupe', 'maxEdge', 'x', 'y', 'z'] as const satisfies readonly (keyof TerrainOptions)[];
