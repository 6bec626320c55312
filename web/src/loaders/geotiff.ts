// GeoTIFF DEMs as points: one point per cell with data, at the cell's centre
// (the sample's own location for PixelIsPoint rasters). The file's structure is
// read and checked here (tiff/raster.ts) before anything is decoded; the geotiff
// package decompresses the chunks (Deflate, PackBits, ZSTD), and LZW goes through
// tiff/lzw.ts, which bounds its output by the chunk's size.
import { fail } from './fail.js';
import { decodeRaster } from './tiff/decode.js';
import { Directory } from './tiff/ifd.js';
import { describeRaster } from './tiff/raster.js';
import type { PointCloud } from './types.js';

export interface GeoTIFFOptions {
  /** The band read as heights (0-based; default 0). */
  band?: number;
}

/** A raster's default domain in cells (Terrain.maxEdge = this many cell sides):
 * the core's kRasterMaxEdgeCells (domain.hpp), which ASCII grids get. */
export const RASTER_MAX_EDGE_CELLS = 3;

export async function readGeoTIFF(bytes: Uint8Array | ArrayBuffer, options: GeoTIFFOptions = {}): Promise<PointCloud> {
  // (a plain view: a Node Buffer's slice() shares memory instead of copying)
  const data = bytes instanceof Uint8Array ? new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength) : new Uint8Array(bytes);
  const raster = describeRaster(new Directory(data), options.band ?? 0);
  const { width, height, transform: t, half } = raster;
  const z = await decodeRaster(data, raster);
  let cells = 0;
  for (let i = 0; i < z.length; ++i) if (z[i] === z[i]) ++cells; // (NaN: no data)
  const xyz = new Float64Array(3 * cells);
  const cellOf = new Uint32Array(cells);
  let n = 0;
  for (let row = 0; row < height; ++row) {
    for (let col = 0; col < width; ++col) {
      const h = z[row * width + col]!;
      if (h !== h) continue;
      cellOf[n / 3] = row * width + col;
      const u = col + half;
      const v = row + half;
      xyz[n++] = t[0] * u + t[1] * v + t[2]; // (t[1] * v is 0 for unrotated rasters: exact)
      xyz[n++] = t[3] * u + t[4] * v + t[5];
      xyz[n++] = h;
    }
  }
  if (cells === 0) fail('GeoTIFF', `every one of the ${width * height} cells is without data (NODATA ${raster.nodataText ?? 'or not finite'})`);
  const skipped = width * height - cells;
  const warnings: string[] = [];
  if (skipped > 0) warnings.push(`skipped ${skipped} of ${width * height} cells without data (NODATA ${raster.nodataText ?? 'or not finite'})`);
  // The default domain of a raster with gaps (the core's kRasterMaxEdgeCells):
  // 3 times the longer cell side.
  const maxEdge = skipped > 0 ? RASTER_MAX_EDGE_CELLS * Math.max(Math.hypot(t[0], t[3]), Math.hypot(t[1], t[4])) : undefined;
  const origin = (i: number) => `row ${Math.floor(cellOf[i]! / width)}, column ${cellOf[i]! % width}`;
  return { xyz, ...(raster.crs ? { crs: raster.crs } : {}), warnings, ...(maxEdge ? { maxEdge } : {}), origin };
}
