// Corrupted GIS files, each named after what it reproduces, made from the valid
// fixtures one directory up by changing the fields named below. Each is a file
// the loaders once crashed on, hung on, leaked on or read silently wrong; the
// tests (tests/js/loaders-corrupt.test.ts) expect each to be refused in one line.
//
//   node tests/fixtures-gis/corrupt/make.mjs
import { readFileSync, writeFileSync } from 'node:fs';

const here = new URL('./', import.meta.url).pathname;
const read = (name) => new Uint8Array(readFileSync(`${here}../${name}`));

// A classic little-endian TIFF's first-IFD entry for `tag`: where its fields are.
function entry(b, tag) {
  const v = new DataView(b.buffer);
  const first = v.getUint32(4, true);
  for (let i = 0; i < v.getUint16(first, true); ++i) {
    const e = first + 2 + 12 * i;
    if (v.getUint16(e, true) === tag) return { e, v, value: v.getUint32(e + 8, true) };
  }
  throw new Error(`no tag ${tag}`);
}
// Sets the tag's single value: a SHORT, or as a LONG (type 4) when `long`.
const setTiff = (b, tag, value, long = false) => {
  const { e, v } = entry(b, tag);
  if (long) {
    v.setUint16(e + 2, 4, true);
    v.setUint32(e + 8, value, true);
  } else v.setUint16(e + 8, value, true);
  return b;
};

const COMPRESSION = 259, IMAGE_LENGTH = 257, ROWS_PER_STRIP = 278, STRIP_OFFSETS = 273, STRIP_BYTE_COUNTS = 279, PIXEL_SCALE = 33550;

export const FILES = {
  // One byte of the LZW data set to 0: geotiff's decoder followed a cycle in its
  // table into an ever-growing array, and V8 aborted the process.
  'lzw-byte-zeroed.tif': () => {
    const b = read('dem-utm-int16-lzw.tif');
    b[450] = 0;
    return b;
  },
  // ImageLength 16,777,221 with RowsPerStrip as large: one strip of 671 million
  // cells claimed by a 425-byte strip (ran a minute and reached 4 GB).
  'height-16777221.tif': () => setTiff(setTiff(read('dem-utm-int16-lzw.tif'), IMAGE_LENGTH, 16777221, true), ROWS_PER_STRIP, 16777221, true),
  // 100,000 rows in one strip: 8 MB of samples from 425 bytes of LZW, more than LZW can hold.
  'strip-too-short-for-its-rows.tif': () => setTiff(setTiff(read('dem-utm-int16-lzw.tif'), IMAGE_LENGTH, 100000, true), ROWS_PER_STRIP, 100000, true),
  // StripOffsets renamed to an unknown tag: every height was read as 0.
  'no-strip-offsets.tif': () => {
    const b = read('dem-utm-int16-lzw.tif');
    const { e, v } = entry(b, STRIP_OFFSETS);
    v.setUint16(e, 65000, true);
    return b;
  },
  // StripByteCounts 0: every height was read as 0.
  'strip-byte-count-0.tif': () => setTiff(read('dem-utm-int16-lzw.tif'), STRIP_BYTE_COUNTS, 0, true),
  // Uncompressed samples flagged ZSTD: every height was read as 0.
  'raw-flagged-zstd.tif': () => setTiff(read('dem-utm-float64-pixel-is-point.tif'), COMPRESSION, 50000),
  // Uncompressed samples flagged LZW: heights like 1e36 and 1e-38, and a stray line on stderr.
  'raw-flagged-lzw.tif': () => setTiff(read('dem-utm-float64-pixel-is-point.tif'), COMPRESSION, 5),
  // ModelPixelScale's first value NaN: reported as "line 1: x is 'NaN'".
  'pixel-scale-nan.tif': () => {
    const b = read('dem-utm-int16-lzw.tif');
    new DataView(b.buffer).setFloat64(entry(b, PIXEL_SCALE).value, NaN, true);
    return b;
  },
  // ModelPixelScale 1e308: the raster's far corner at an infinite coordinate,
  // read as points at -Infinity (a loader fuzzer finding).
  'pixel-scale-1e308.tif': () => {
    const b = read('dem-utm-int16-lzw.tif');
    new DataView(b.buffer).setFloat64(entry(b, PIXEL_SCALE).value, 1e308, true);
    return b;
  },
  // The first IFD's offset past the end of the file: "Offset is outside the bounds of the DataView".
  'ifd-offset-past-end.tif': () => {
    const b = read('dem-utm-int16-lzw.tif');
    new DataView(b.buffer).setUint32(4, 1 << 20, true);
    return b;
  },
  // LAS record length 0 and 10,000,000 points: the same record read ten million times (33 s, 2.75 GB).
  'record-length-0.las': () => {
    const b = read('lidar-point10.las');
    const v = new DataView(b.buffer);
    v.setUint16(105, 0, true);
    v.setUint32(107, 10_000_000, true);
    return b;
  },
  // A header promising 100,000,000 points: two 2.4 GB arrays allocated before any check.
  'count-100000000.las': () => {
    const b = read('lidar-point10.las');
    new DataView(b.buffer).setUint32(107, 100_000_000, true);
    return b;
  },
  'count-100000000.laz': () => {
    const b = read('lidar-point10.laz');
    new DataView(b.buffer).setUint32(107, 100_000_000, true);
    return b;
  },
  // The point data offset inside the header: header bytes were read as 48 points.
  'point-offset-in-header.las': () => {
    const b = read('lidar-point10.las');
    new DataView(b.buffer).setUint32(96, 100, true);
    return b;
  },
  // Record length 12, shorter than format 0's 20 bytes: overlapping records.
  'record-length-12.las': () => {
    const b = read('lidar-point10.las');
    new DataView(b.buffer).setUint16(105, 12, true);
    return b;
  },
  // Point format 6 declared on format 0's 20-byte records: the class was read from the wrong byte.
  'format-6-on-20-byte-records.las': () => {
    const b = read('lidar-point10.las');
    b[104] = 6;
    return b;
  },
  // Compressed bytes overwritten in the middle of the LAZ chunk: LASzip's C++
  // exception came out as "1143624 - Exception catching is disabled ...".
  'laz-chunk-overwritten.laz': () => {
    const b = read('lidar-point10.laz');
    const offset = new DataView(b.buffer).getUint32(96, true);
    for (let i = offset + 200; i < offset + 400; ++i) b[i] = (i * 151) & 255;
    return b;
  },
};

if (process.argv[1] === new URL(import.meta.url).pathname)
  for (const [name, make] of Object.entries(FILES)) writeFileSync(`${here}${name}`, make());
