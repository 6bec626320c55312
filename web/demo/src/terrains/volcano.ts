import volcano from 'vega-data/volcano.json';
import type { HeightGrid } from './grid.ts';
import { jitteredSample } from './sample.ts';

/** Maunga Whau (Mt Eden, Auckland): 87 x 61 heights in metres on a 10 m grid. */
export const volcanoGrid: HeightGrid = {
  width: volcano.width,
  height: volcano.height,
  values: volcano.values,
  spacing: 10,
};

/** About `count` points sampled from the volcano (jittered), x, y, z in metres. */
export function volcanoPoints(count = 1500, seed = 7): Float64Array {
  return jitteredSample(volcanoGrid, count, seed);
}
