// Opt-in loaders for GIS files (`hodt/loaders`): GeoTIFF DEMs and LAS/LAZ point
// clouds to points. Kept out of the core bundle: import them only if you read
// such files.
import { readGeoTIFF } from './geotiff.js';
import { readLAS, type LASOptions } from './las.js';
import { sniffFormat } from './sniff.js';
import type { PointCloud } from './types.js';

export { readGeoTIFF, RASTER_MAX_EDGE_CELLS, type GeoTIFFOptions } from './geotiff.js';
export { readLAS, type LASOptions } from './las.js';
export type { PointCloud } from './types.js';
export { sniffFormat, type BinaryFormat } from './sniff.js';

/** Reads a GeoTIFF or LAS/LAZ file (by its content); null for any other file. */
export async function readPointFile(bytes: Uint8Array, options: LASOptions = {}): Promise<PointCloud | null> {
  const format = sniffFormat(bytes);
  if (format === 'geotiff') return readGeoTIFF(bytes);
  if (format === 'las') return readLAS(bytes, options);
  return null;
}
