import { HodtError, type Hodt, type Terrain } from 'hodt';
import { readStructure, type Structure } from './analysis.ts';

export type Built = { ok: true; terrain: Terrain; structure: Structure } | { ok: false; message: string };

/** Builds the terrain of points within the domain of maxEdge (null: none), or
 * says why not in words for the user (the library's message names the point
 * index and what is wrong). */
export function buildTerrain(hodt: Hodt, points: Float64Array, maxEdge: number | null, withValues = true): Built {
  let terrain: Terrain | null = null;
  try {
    terrain = hodt.terrain(points, { maxEdge });
    return { ok: true, terrain, structure: readStructure(terrain, withValues) };
  } catch (e) {
    terrain?.dispose();
    if (e instanceof HodtError) return { ok: false, message: e.message };
    throw e;
  }
}
