// Opt-in loaders for GIS files (`hodt/loaders`): GeoTIFF DEMs and LAS/LAZ point
// clouds to points. Kept out of the core bundle: import them only if you read
// such files.
import { readGeoTIFF } from './geotiff.js';
import { readLAS, type LASOptions } from './las.js';
import type { PointCloud } from './types.js';

export { readGeoTIFF, RASTER_MAX_EDGE_CELLS, type GeoTIFFOptions } from './geotiff.js';
export { readLAS, type LASOptions } from './las.js';
export type { PointCloud } from './types.js';

export type BinaryFormat = 'geotiff' | 'las';

/** The GIS format a file's first bytes announce, or null (text, or unknown). */
export function sniffFormat(bytes: Uint8Array): BinaryFormat | null {
  const [a, b, c, d] = [bytes[0], bytes[1], bytes[2], bytes[3]];
  if ((a === 0x49 && b === 0x49 && (c === 42 || c === 43) && d === 0) || (a === 0x4d && b === 0x4d && c === 0 && (d === 42 || d === 43)))
    return 'geotiff';
  if (a === 0x4c && b === 0x41 && c === 0x53 && d === 0x46) return 'las'; // "LASF", also LAZ
  return null;
}

/** Reads a GeoTIFF or LAS/LAZ file (by its content); null for any other file. */
export async function readPointFile(bytes: Uint8Array, options: LASOptions = {}): Promise<PointCloud | null> {
  const format = sniffFormat(bytes);
  if (format === 'geotiff') return readGeoTIFF(bytes);
  if (format === 'las') return readLAS(bytes, options);
  return null;
}
