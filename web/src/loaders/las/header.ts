// A LAS/LAZ public header block (LAS 1.0 to 1.4), every field this reader uses
// checked against the specification and the file's length before any point is
// read: the header and its variable length records fit before the point data,
// records are at least as long as their format, and an uncompressed file holds
// every point it promises.
import { fail } from '../fail.js';

/** The smallest record of each point data record format (LAS 1.4, Table 7 on). */
export const RECORD_LENGTH = [20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67];

/** The smallest header of each minor version (1.0 to 1.4). */
const HEADER_SIZE = [227, 227, 227, 235, 375];

export interface Header {
  minor: number;
  format: number; // point data record format, without the compression bits
  compressed: boolean;
  recordLength: number;
  offset: number; // to the first point
  count: number;
  scale: [number, number, number];
  origin: [number, number, number];
  crs?: string;
  /** LAZ: the laszip VLR's chunk size (0xffffffff: chunks of varying size). */
  chunkSize?: number;
}

export function readHeader(bytes: Uint8Array): Header {
  const n = bytes.length;
  if (n < 227) fail('LAS', `the file has ${n} bytes, shorter than a LAS header (227)`);
  const v = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const major = bytes[24]!;
  const minor = bytes[25]!;
  if (major !== 1 || minor > 4) fail('LAS', `version ${major}.${minor}, expected 1.0 to 1.4`);
  const headerSize = v.getUint16(94, true);
  if (headerSize < HEADER_SIZE[minor]! || headerSize > n)
    fail('LAS', `header size ${headerSize}, expected ${HEADER_SIZE[minor]} or more for LAS 1.${minor}, within the file's ${n} bytes`);
  const offset = v.getUint32(96, true);
  const vlrCount = v.getUint32(100, true);
  const formatByte = bytes[104]!;
  const format = formatByte & 0x3f;
  const compressed = (formatByte & 0xc0) !== 0;
  const recordLength = v.getUint16(105, true);
  if (format > 10) fail('LAS', `point data record format ${format}, expected 0 to 10`);
  if (minor < 4 && format > 5) fail('LAS', `point data record format ${format} in a LAS 1.${minor} file (formats 6 to 10 are LAS 1.4)`);
  if (recordLength < RECORD_LENGTH[format]!)
    fail('LAS', `point record length ${recordLength}, expected at least ${RECORD_LENGTH[format]} for point format ${format}`);
  const legacy = v.getUint32(107, true);
  let count = legacy;
  if (minor >= 4) {
    const big = v.getBigUint64(247, true);
    const extended = big > BigInt(Number.MAX_SAFE_INTEGER) ? Number.MAX_SAFE_INTEGER : Number(big);
    if (legacy !== 0 && extended !== 0 && legacy !== extended)
      fail('LAS', `the header's point counts disagree: ${legacy} (legacy) and ${extended}`);
    count = extended || legacy;
  }
  if (count === 0) fail('LAS', 'the header says the file holds no points');
  const scale: Header['scale'] = [v.getFloat64(131, true), v.getFloat64(139, true), v.getFloat64(147, true)];
  const origin: Header['origin'] = [v.getFloat64(155, true), v.getFloat64(163, true), v.getFloat64(171, true)];
  if (!scale.every((s) => Number.isFinite(s) && s !== 0)) fail('LAS', `scale factors (${scale.join(', ')}), expected finite non-zero numbers`);
  if (!origin.every(Number.isFinite)) fail('LAS', `offsets (${origin.join(', ')}), expected finite numbers`);

  // Stored coordinates are 32-bit integers: each scaled and offset one finite.
  for (let a = 0; a < 3; ++a)
    if (!Number.isFinite(2 ** 31 * Math.abs(scale[a]!) + Math.abs(origin[a]!)))
      fail('LAS', `${'xyz'[a]} scale ${scale[a]} and offset ${origin[a]} take coordinates past the largest double`);
  if (offset > n) fail('LAS', `point data offset ${offset} is past the end of the file (${n} bytes)`);
  const h: Header = { minor, format, compressed, recordLength, offset, count, scale, origin };
  // The variable length records lie between the header and the point data.
  let at = headerSize;
  for (let i = 0; i < vlrCount; ++i) {
    if (at + 54 > offset) fail('LAS', `variable length record ${i} of ${vlrCount} starts at byte ${at}, past the point data offset (${offset})`);
    const user = String.fromCharCode(...bytes.subarray(at + 2, at + 18)).replace(/\0[\s\S]*$/, '');
    const record = v.getUint16(at + 18, true);
    const length = v.getUint16(at + 20, true);
    const data = at + 54;
    if (data + length > offset)
      fail('LAS', `variable length record ${i} (${length} bytes at byte ${data}) runs past the point data offset (${offset})`);
    if (user === 'LASF_Projection' && record === 34735) h.crs = epsgOf(v, data, length);
    if (user === 'laszip encoded' && record === 22204 && length >= 16) h.chunkSize = v.getUint32(data + 12, true);
    at = data + length;
  }
  if (offset < at) fail('LAS', `point data offset ${offset} lies inside the header and its records (${at} bytes)`);
  if (offset >= n) fail('LAS', `point data offset ${offset} is at or past the end of the file (${n} bytes)`);
  if (compressed && h.chunkSize === undefined) fail('LAZ', 'the laszip VLR (laszip encoded, 22204) is missing: the points cannot be decompressed');
  if (!compressed && offset + count * recordLength > n)
    fail('LAS', `the header promises ${count} points of ${recordLength} bytes from byte ${offset}; the file has ${n} bytes, room for ${Math.floor((n - offset) / recordLength)}`);
  return h;
}

// The CRS of a GeoTIFF key directory record: the projected or geographic EPSG code.
function epsgOf(v: DataView, data: number, length: number): string | undefined {
  if (length < 8) return undefined;
  const keys = v.getUint16(data + 6, true);
  let crs: string | undefined;
  for (let k = 0; k < keys && 16 + 8 * k <= length; ++k) {
    const e = data + 8 + 8 * k;
    const id = v.getUint16(e, true);
    const location = v.getUint16(e + 2, true);
    const value = v.getUint16(e + 6, true);
    if (location === 0 && (id === 3072 || (id === 2048 && !crs)) && value > 0 && value < 32767) crs = `EPSG:${value}`;
  }
  return crs;
}
