// What a GeoTIFF's first image is, from its directory, checked against the TIFF
// rules and the file's length: the sample layout, the chunks (strips or tiles)
// that hold the band read, the georeferencing, NODATA and the CRS. Each chunk's
// decoded size must be one its stored bytes can hold under its compression, so
// that the dimensions a corrupted header claims cannot ask for more memory or
// time than the file justifies.
import { fail, quoted } from '../fail.js';
import type { Directory } from './ifd.js';

/** Compressions read, with the largest ratio of decoded to stored bytes each
 * format allows: PackBits 128 bytes per 2; Deflate's longest match, 258 bytes,
 * from one code of at least 2 bits (1032); an LZW code of 9 or more bits yields
 * at most 4096 bytes; ZSTD's RLE block stores up to 128 KiB in 4 bytes. (LERC is
 * not read: its blobs' own headers size its allocations, which nothing here
 * could bound.) */
const COMPRESSIONS = new Map<number, { name: string; ratio: number }>([
  [1, { name: 'none', ratio: 1 }],
  [5, { name: 'LZW', ratio: 4096 }],
  [8, { name: 'Deflate', ratio: 1032 }],
  [32946, { name: 'Deflate', ratio: 1032 }],
  [32773, { name: 'PackBits', ratio: 64 }],
  [50000, { name: 'ZSTD', ratio: 32768 }],
]);

/** The most cells a raster may have: the core's limit for ASCII grids. */
export const MAX_CELLS = 5e7;

const PIXEL_IS_POINT = 2; // GTRasterTypeGeoKey

export interface Chunk {
  offset: number;
  byteCount: number;
  /** Rows of the image this chunk covers (the last strip may be shorter). */
  rows: number;
}

export interface Raster {
  width: number;
  height: number;
  little: boolean;
  samplesPerPixel: number;
  bitsPerSample: number[];
  /** 1 unsigned, 2 signed, 3 floating point, of the band read. */
  sampleFormat: number;
  /** Bytes of the band's sample, and where it starts within a pixel of its chunk. */
  sampleBytes: number;
  sampleOffset: number;
  /** Bytes of one pixel within a chunk (every sample when interleaved). */
  pixelBytes: number;
  planar: number;
  compression: number;
  compressionName: string;
  predictor: number;
  tiled: boolean;
  chunkWidth: number;
  chunkHeight: number;
  chunksAcross: number;
  /** The chunks holding the band, row by row of chunks. */
  chunks: Chunk[];
  /** The NODATA value as the samples hold it, and as the file writes it. */
  nodata?: number;
  nodataText?: string;
  /** x = t0 col + t1 row + t2, y = t3 col + t4 row + t5 at raster position (col, row). */
  transform: [number, number, number, number, number, number];
  /** Where a cell's point lies within it: 0.5 (its centre) or 0 (PixelIsPoint). */
  half: number;
  crs?: string;
}

export function describeRaster(dir: Directory, band: number): Raster {
  const width = dir.integer('ImageWidth', undefined, 1, 2 ** 31);
  const height = dir.integer('ImageLength', undefined, 1, 2 ** 31);
  if (width * height > MAX_CELLS) fail('GeoTIFF', `the raster is ${width} x ${height} cells, more than ${MAX_CELLS} (the most hodt reads)`);
  const samplesPerPixel = dir.integer('SamplesPerPixel', 1, 1, 256);
  if (!(Number.isInteger(band) && band >= 0 && band < samplesPerPixel))
    fail('GeoTIFF', `band ${band} does not exist (the raster has ${samplesPerPixel})`);
  const bitsPerSample = perSample(dir.numbers('BitsPerSample') ?? [1], samplesPerPixel, 'BitsPerSample');
  const formats = perSample(dir.numbers('SampleFormat') ?? [1], samplesPerPixel, 'SampleFormat');
  for (const bits of bitsPerSample)
    if (![8, 16, 32, 64].includes(bits)) fail('TIFF', `tag BitsPerSample (258) is ${bits}, expected 8, 16, 32 or 64 bits per sample`);
  const sampleFormat = formats[band]!;
  const sampleBits = bitsPerSample[band]!;
  const readable = sampleFormat === 3 ? sampleBits === 32 || sampleBits === 64 : (sampleFormat === 1 || sampleFormat === 2) && sampleBits <= 32;
  if (!readable)
    fail('GeoTIFF', `band ${band} holds ${sampleBits}-bit samples of SampleFormat ${sampleFormat}; expected 8 to 32-bit integers (1, 2) or 32/64-bit floats (3)`);
  const planar = dir.integer('PlanarConfiguration', 1, 1, 2);
  const compression = dir.integer('Compression', 1, 0, 65535);
  const codec = COMPRESSIONS.get(compression);
  if (!codec)
    fail('GeoTIFF', `compression ${compression} is not one hodt reads (none, LZW, Deflate, PackBits, ZSTD); gdal_translate -co COMPRESS=DEFLATE converts it`);
  const predictor = dir.integer('Predictor', 1, 1, 3);
  const little = dir.little;
  if (predictor === 3 && sampleFormat !== 3) fail('TIFF', 'tag Predictor (317) is 3 (floating point) on integer samples');
  if (predictor === 2 && sampleFormat === 3) fail('TIFF', 'tag Predictor (317) is 2 (integer differences) on floating point samples');
  if (predictor !== 1 && bitsPerSample.some((b) => b !== sampleBits)) fail('TIFF', 'tag Predictor (317) is set on samples of different sizes');
  if (predictor === 2 && !little && sampleBits > 8) fail('GeoTIFF', 'big-endian samples with Predictor 2 are not read; gdal_translate converts them');

  const bytesOf = bitsPerSample.map((b) => b / 8);
  const sampleBytes = bytesOf[band]!;
  const pixelBytes = planar === 1 ? bytesOf.reduce((a, b) => a + b, 0) : sampleBytes;
  const sampleOffset = planar === 1 ? bytesOf.slice(0, band).reduce((a, b) => a + b, 0) : 0;

  // The chunks: tiles if the directory has tile tags, else strips.
  const tiled = dir.has('TileOffsets') || dir.has('TileWidth');
  const chunkWidth = tiled ? dir.integer('TileWidth', undefined, 1, 2 ** 31) : width;
  const rowsPerStrip = tiled ? 0 : dir.integer('RowsPerStrip', height, 1, 2 ** 32 - 1);
  const chunkHeight = tiled ? dir.integer('TileLength', undefined, 1, 2 ** 31) : Math.min(rowsPerStrip, height);
  if (chunkWidth * chunkHeight > 4 * MAX_CELLS) fail('TIFF', `a ${tiled ? 'tile' : 'strip'} of ${chunkWidth} x ${chunkHeight} cells is larger than any raster hodt reads`);
  const chunksAcross = Math.ceil(width / chunkWidth);
  const chunksDown = Math.ceil(height / chunkHeight);
  const perPlane = chunksAcross * chunksDown;
  const [offsetsTag, countsTag] = tiled ? (['TileOffsets', 'TileByteCounts'] as const) : (['StripOffsets', 'StripByteCounts'] as const);
  const offsets = dir.numbers(offsetsTag);
  const byteCounts = dir.numbers(countsTag);
  const kind = tiled ? 'tile' : 'strip';
  if (!offsets) fail('TIFF', `tag ${offsetsTag} is missing: the file does not say where its ${kind}s are`);
  if (!byteCounts) fail('TIFF', `tag ${countsTag} is missing: the file does not say how long its ${kind}s are`);
  const expected = perPlane * (planar === 2 ? samplesPerPixel : 1);
  for (const [name, values] of [[offsetsTag, offsets], [countsTag, byteCounts]] as const)
    if (values.length !== expected)
      fail('TIFF', `tag ${name} has ${values.length} values; a ${width} x ${height} raster in ${kind}s of ${chunkWidth} x ${chunkHeight}${planar === 2 ? ` with ${samplesPerPixel} planes` : ''} has ${expected}`);

  const nodataText = dir.text('GDAL_NODATA')?.trim();
  let nodata: number | undefined;
  if (nodataText !== undefined && nodataText !== '') {
    const value = /^[+-]?(nan|inf(inity)?)$/i.test(nodataText) ? (/nan/i.test(nodataText) ? NaN : nodataText.startsWith('-') ? -Infinity : Infinity) : Number(nodataText);
    if (Number.isNaN(value) && !/nan/i.test(nodataText)) fail('GeoTIFF', `GDAL_NODATA (42113) is ${quoted(nodataText)}, expected a number`);
    // NODATA compared with samples as they are stored: a float32 raster holds it rounded.
    nodata = sampleFormat === 3 && sampleBits === 32 ? Math.fround(value) : value;
  }

  const file = dir.length;
  const first = planar === 2 ? band * perPlane : 0;
  const chunks: Chunk[] = [];
  for (let i = 0; i < perPlane; ++i) {
    const offset = offsets[first + i]!;
    const byteCount = byteCounts[first + i]!;
    const down = Math.floor(i / chunksAcross);
    const rows = tiled ? chunkHeight : Math.min(chunkHeight, height - down * chunkHeight);
    const where = `${kind} ${first + i}`;
    if (!Number.isInteger(offset) || !Number.isInteger(byteCount) || offset < 0 || byteCount < 0)
      fail('TIFF', `${where}: offset ${offset} and byte count ${byteCount}, expected whole numbers of bytes`);
    if (byteCount === 0) {
      // GDAL's sparse files leave a chunk out (offset 0, byte count 0) when it holds only NODATA.
      if (offset === 0 && nodata !== undefined) {
        chunks.push({ offset, byteCount, rows });
        continue;
      }
      fail('TIFF', `${where} has ${countsTag} 0: its data are missing`);
    }
    if (offset + byteCount > file) fail('TIFF', `${where}: ${byteCount} bytes at offset ${offset} run past the end of the file (${file} bytes)`);
    const decoded = chunkWidth * rows * pixelBytes;
    if (compression === 1 ? byteCount < decoded : decoded > byteCount * codec.ratio)
      fail('TIFF', `${where}: ${byteCount} bytes of ${codec.name} data cannot hold its ${chunkWidth} x ${rows} cells (${decoded} bytes)`);
    chunks.push({ offset, byteCount, rows });
  }

  const { transform, half, crs } = georeferencing(dir);
  checkCorners(transform, width, height);
  return {
    width, height, little, samplesPerPixel, bitsPerSample, sampleFormat, sampleBytes, sampleOffset, pixelBytes, planar,
    compression, compressionName: codec.name, predictor, tiled, chunkWidth, chunkHeight, chunksAcross, chunks,
    ...(nodata !== undefined ? { nodata, nodataText } : {}), transform, half,
    ...(crs ? { crs } : {}),
  };
}

// A per-sample tag: one value for every sample (or one for all).
function perSample(values: number[], samples: number, name: string): number[] {
  if (values.length === 1) return new Array<number>(samples).fill(values[0]!);
  if (values.length < samples) fail('TIFF', `tag ${name} has ${values.length} values for ${samples} samples per pixel`);
  return values.slice(0, samples);
}

const shown = (values: number[] | undefined, count: number) => (values ?? []).slice(0, count).join(', ');

function finite(values: number[] | undefined, count: number): values is number[] {
  return values !== undefined && values.length >= count && values.slice(0, count).every(Number.isFinite);
}

function georeferencing(dir: Directory): Pick<Raster, 'transform' | 'half' | 'crs'> {
  const tie = dir.numbers('ModelTiepoint');
  const scale = dir.numbers('ModelPixelScale');
  const matrix = dir.numbers('ModelTransformation');
  let transform: Raster['transform'];
  if (tie || scale) {
    if (!finite(tie, 6)) fail('GeoTIFF', `ModelTiepoint (33922) is (${shown(tie, 6)}), expected 6 finite numbers`);
    if (!finite(scale, 2) || scale[0] === 0 || scale[1] === 0)
      fail('GeoTIFF', `ModelPixelScale (33550) is (${shown(scale, 3)}), expected finite non-zero cell sizes`);
    const [a, e] = [scale[0]!, -scale[1]!];
    transform = [a, 0, tie[3]! - tie[0]! * a, 0, e, tie[4]! - tie[1]! * e];
  } else if (matrix) {
    if (!finite(matrix, 16)) fail('GeoTIFF', 'ModelTransformation (34264) holds a value that is not a finite number, or fewer than 16');
    transform = [matrix[0]!, matrix[1]!, matrix[3]!, matrix[4]!, matrix[5]!, matrix[7]!];
    if (transform[0] * transform[4] - transform[1] * transform[3] === 0) fail('GeoTIFF', 'ModelTransformation (34264) maps the raster onto a line');
  } else {
    fail('GeoTIFF', 'no georeferencing (ModelTiepoint and ModelPixelScale, or ModelTransformation)');
  }
  return { transform, ...keysOf(dir) };
}

// The raster's corners: where the affine map is finite, it is finite on every cell.
export function checkCorners(t: Raster['transform'], width: number, height: number): void {
  for (const [u, v] of [[0, 0], [width, 0], [0, height], [width, height]] as const)
    if (!Number.isFinite(t[0] * u + t[1] * v + t[2]) || !Number.isFinite(t[3] * u + t[4] * v + t[5]))
      fail('GeoTIFF', `the georeferencing puts the raster's corner (column ${u}, row ${v}) at an infinite coordinate`);
}

function keysOf(dir: Directory): Pick<Raster, 'half' | 'crs'> {
  const keys = geoKeys(dir.numbers('GeoKeyDirectory'));
  const half = keys.get(1025) === PIXEL_IS_POINT ? 0 : 0.5;
  const epsg = keys.get(3072) ?? keys.get(2048);
  const crs = epsg !== undefined && epsg > 0 && epsg < 32767 ? `EPSG:${epsg}` : undefined;
  return { half, ...(crs ? { crs } : {}) };
}

// The GeoKey directory's keys whose value is stored in the directory itself.
function geoKeys(directory: number[] | undefined): Map<number, number> {
  const keys = new Map<number, number>();
  if (!directory) return keys;
  if (directory.length < 4) fail('GeoTIFF', `GeoKeyDirectory (34735) has ${directory.length} values, shorter than its header (4)`);
  const count = directory[3]!;
  if (4 + 4 * count > directory.length) fail('GeoTIFF', `GeoKeyDirectory (34735) names ${count} keys but holds ${Math.floor((directory.length - 4) / 4)}`);
  for (let k = 0; k < count; ++k) {
    const [id, location, , value] = directory.slice(4 + 4 * k, 8 + 4 * k) as [number, number, number, number];
    if (location === 0) keys.set(id, value);
  }
  return keys;
}
