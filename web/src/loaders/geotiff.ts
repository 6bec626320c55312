// GeoTIFF DEMs as points: one point per cell with data, at the cell's centre
// (the sample's own location for PixelIsPoint rasters), through the geotiff
// package (any sample type, tiled or stripped, compressed or not).
import { fromArrayBuffer } from 'geotiff';
import type { PointCloud } from './types.js';

const PIXEL_IS_POINT = 2; // GTRasterTypeGeoKey

export interface GeoTIFFOptions {
  /** The band read as heights (0-based; default 0). */
  band?: number;
}

function arrayBufferOf(bytes: Uint8Array | ArrayBuffer): ArrayBuffer {
  if (bytes instanceof ArrayBuffer) return bytes;
  return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
}

/** A raster's default domain in cells (Terrain.maxEdge = this many cell sides):
 * the core's kRasterMaxEdgeCells (domain.hpp), which ASCII grids get. */
export const RASTER_MAX_EDGE_CELLS = 3;

export async function readGeoTIFF(bytes: Uint8Array | ArrayBuffer, options: GeoTIFFOptions = {}): Promise<PointCloud> {
  const tiff = await fromArrayBuffer(arrayBufferOf(bytes));
  const image = await tiff.getImage();
  const width = image.getWidth();
  const height = image.getHeight();
  const band = options.band ?? 0;
  if (!(Number.isInteger(band) && band >= 0 && band < image.getSamplesPerPixel()))
    throw new Error(`GeoTIFF: band ${band} does not exist (the raster has ${image.getSamplesPerPixel()})`);
  const dir = image.fileDirectory;
  const tie = dir.getValue('ModelTiepoint') as number[] | undefined;
  const scale = dir.getValue('ModelPixelScale') as number[] | undefined;
  const transform = dir.getValue('ModelTransformation') as number[] | undefined;
  // x = a*col + b*row + c, y = d*col + e*row + f, at the raster position (col, row).
  let a: number, b: number, c: number, d: number, e: number, f: number;
  if (tie && tie.length >= 6 && scale && scale.length >= 2) {
    [a, b, d, e] = [scale[0]!, 0, 0, -scale[1]!];
    c = tie[3]! - tie[0]! * a;
    f = tie[4]! - tie[1]! * e;
  } else if (transform && transform.length >= 16) {
    [a, b, c, d, e, f] = [transform[0]!, transform[1]!, transform[3]!, transform[4]!, transform[5]!, transform[7]!];
  } else {
    throw new Error('GeoTIFF: no georeferencing (ModelTiepoint and ModelPixelScale, or ModelTransformation)');
  }
  const keys = image.getGeoKeys() ?? {};
  const half = keys.GTRasterTypeGeoKey === PIXEL_IS_POINT ? 0 : 0.5;
  const nodata = image.getGDALNoData();
  const raster = (await image.readRasters({ samples: [band] }))[0] as ArrayLike<number>;
  const xyz = new Float64Array(width * height * 3);
  let n = 0;
  let skipped = 0;
  for (let row = 0; row < height; ++row) {
    for (let col = 0; col < width; ++col) {
      const z = raster[row * width + col]!;
      if (!Number.isFinite(z) || (nodata !== null && z === nodata)) {
        ++skipped;
        continue;
      }
      const u = col + half;
      const v = row + half;
      xyz[n++] = a * u + b * v + c; // (b * v is 0 for unrotated rasters: exact)
      xyz[n++] = d * u + e * v + f;
      xyz[n++] = z;
    }
  }
  const warnings: string[] = [];
  if (skipped > 0) warnings.push(`skipped ${skipped} of ${width * height} cells without data (NODATA ${nodata ?? 'or not finite'})`);
  const epsg = keys.ProjectedCSTypeGeoKey ?? keys.GeographicTypeGeoKey;
  const crs = typeof epsg === 'number' && epsg > 0 && epsg < 32767 ? `EPSG:${epsg}` : undefined;
  // The default domain of a raster with gaps (the core's kRasterMaxEdgeCells):
  // 3 times the longer cell side.
  const maxEdge = skipped > 0 ? RASTER_MAX_EDGE_CELLS * Math.max(Math.hypot(a, d), Math.hypot(b, e)) : undefined;
  return { xyz: xyz.subarray(0, n), ...(crs ? { crs } : {}), warnings, ...(maxEdge ? { maxEdge } : {}) };
}
