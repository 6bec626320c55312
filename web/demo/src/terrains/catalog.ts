import { fractalPoints } from './fractal.ts';
import type { TerrainKind } from './kinds.ts';
import { jitteredGridPoints } from './jitteredGrid.ts';
import { uniformPoints } from './uniform.ts';
import { volcanoPoints } from './volcano.ts';

/** The built-in terrains, each a function of a point count and a seed. */
export const TERRAINS = {
  volcano: {
    label: 'Volcano (real DEM)',
    about: 'Maunga Whau, Auckland: a 10 m elevation grid, sampled at random points.',
    make: volcanoPoints,
  },
  fractal: {
    label: 'Fractal mountains',
    about: 'Diamond-square fractal terrain: rough, self-similar relief.',
    make: fractalPoints,
  },
  grid: {
    label: 'Jittered grid',
    about: 'A slightly perturbed grid over smooth hills: many flippable quads.',
    make: jitteredGridPoints,
  },
  uniform: {
    label: 'Random uniform',
    about: 'Random positions and random heights: many pits and peaks.',
    make: uniformPoints,
  },
} as const satisfies Record<TerrainKind, { label: string; about: string; make: (n: number, seed: number) => Float64Array }>;

export { TERRAIN_KINDS, type TerrainKind } from './kinds.ts';
