/** The names of the built-in terrains (see catalog.ts), without their generators. */
export const TERRAIN_KINDS = ['volcano', 'fractal', 'grid', 'uniform'] as const;
export type TerrainKind = (typeof TERRAIN_KINDS)[number];

export function isTerrainKind(s: string): s is TerrainKind {
  return (TERRAIN_KINDS as readonly string[]).includes(s);
}
