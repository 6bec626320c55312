// The structure of a TIFF file (classic and BigTIFF): its header and first image
// file directory (IFD), every entry this reader uses checked against the file's
// length before a value is read, so that no count or offset in a corrupted file
// can make a read run past the end or an allocation outgrow the file.
import { fail } from '../fail.js';

/** The size in bytes of one value of each TIFF field type (0: not a type). */
const TYPE_SIZE = [0, 1, 1, 2, 4, 8, 1, 1, 2, 4, 8, 4, 8, 4, 0, 0, 8, 8, 8];
const TYPE_NAME = ['', 'BYTE', 'ASCII', 'SHORT', 'LONG', 'RATIONAL', 'SBYTE', 'UNDEFINED', 'SSHORT', 'SLONG', 'SRATIONAL',
  'FLOAT', 'DOUBLE', 'IFD', '', '', 'LONG8', 'SLONG8', 'IFD8'];

/** The tags this reader uses, by number. */
export const TAG = {
  ImageWidth: 256,
  ImageLength: 257,
  BitsPerSample: 258,
  Compression: 259,
  StripOffsets: 273,
  SamplesPerPixel: 277,
  RowsPerStrip: 278,
  StripByteCounts: 279,
  PlanarConfiguration: 284,
  Predictor: 317,
  TileWidth: 322,
  TileLength: 323,
  TileOffsets: 324,
  TileByteCounts: 325,
  SampleFormat: 339,
  ModelPixelScale: 33550,
  ModelTiepoint: 33922,
  ModelTransformation: 34264,
  GeoKeyDirectory: 34735,
  GDAL_NODATA: 42113,
} as const;
export type TagName = keyof typeof TAG;
const NAME_OF = new Map<number, TagName>(Object.entries(TAG).map(([name, tag]) => [tag, name as TagName]));

interface Entry {
  type: number;
  count: number;
  at: number; // where the values start in the file
}

/** The first IFD of a TIFF file, with typed accessors that check each value. */
export class Directory {
  private readonly view: DataView;
  /** Byte order: true for 'II' (little-endian). */
  readonly little: boolean;
  private readonly entries = new Map<number, Entry>();

  constructor(private readonly bytes: Uint8Array) {
    const n = bytes.length;
    if (n < 8) fail('TIFF', `the file has ${n} bytes, shorter than a TIFF header (8)`);
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.little = bytes[0] === 0x49;
    const version = this.view.getUint16(2, this.little);
    const big = version === 43;
    if (big && (n < 16 || this.view.getUint16(4, this.little) !== 8))
      fail('TIFF', 'BigTIFF header: expected an offset size of 8 bytes');
    const first = big ? this.u64(8) : this.view.getUint32(4, this.little);
    const countSize = big ? 8 : 2;
    const entrySize = big ? 20 : 12;
    const inline = big ? 8 : 4;
    if (first < (big ? 16 : 8) || first + countSize > n)
      fail('TIFF', `the first IFD's offset is ${first}, outside the file's ${n} bytes`);
    const count = big ? this.u64(first) : this.view.getUint16(first, this.little);
    if (count === 0) fail('TIFF', 'the first IFD has no entries');
    if (first + countSize + count * entrySize > n)
      fail('TIFF', `the first IFD's ${count} entries run past the end of the file (${n} bytes)`);
    for (let i = 0; i < count; ++i) {
      const e = first + countSize + i * entrySize;
      const tag = this.view.getUint16(e, this.little);
      const name = NAME_OF.get(tag);
      if (!name) continue; // a tag this reader does not use: not read, not checked
      const type = this.view.getUint16(e + 2, this.little);
      const size = TYPE_SIZE[type] ?? 0;
      if (!size) fail('TIFF', `tag ${name} (${tag}) has field type ${type}, which is not a TIFF type`);
      const valueCount = big ? this.u64(e + 4) : this.view.getUint32(e + 4, this.little);
      const bytesNeeded = valueCount * size;
      const at = bytesNeeded <= inline ? e + (big ? 12 : 8) : big ? this.u64(e + 12) : this.view.getUint32(e + 8, this.little);
      if (valueCount === 0) fail('TIFF', `tag ${name} (${tag}) has no values`);
      if (at + bytesNeeded > n)
        fail('TIFF', `tag ${name} (${tag}): ${valueCount} ${TYPE_NAME[type]} values at offset ${at} run past the end of the file (${n} bytes)`);
      this.entries.set(tag, { type, count: valueCount, at });
    }
  }

  // A LONG8 as a Number; beyond 2^53 it is past the end of any file anyway.
  private u64(at: number): number {
    const value = this.view.getBigUint64(at, this.little);
    return value > BigInt(Number.MAX_SAFE_INTEGER) ? Number.MAX_SAFE_INTEGER : Number(value);
  }

  /** The file's length in bytes. */
  get length(): number {
    return this.bytes.length;
  }

  has(name: TagName): boolean {
    return this.entries.has(TAG[name]);
  }

  /** The tag's values as numbers (integers or floats as stored); undefined when absent. */
  numbers(name: TagName): number[] | undefined {
    const entry = this.entries.get(TAG[name]);
    if (!entry) return undefined;
    const { type, count, at } = entry;
    if (type === 2 || type === 7) fail('TIFF', `tag ${name} (${TAG[name]}) holds ${TYPE_NAME[type]} data, expected numbers`);
    const size = TYPE_SIZE[type]!;
    const out = new Array<number>(count);
    const v = this.view, le = this.little;
    for (let i = 0; i < count; ++i) {
      const p = at + i * size;
      switch (type) {
        case 1: out[i] = v.getUint8(p); break;
        case 6: out[i] = v.getInt8(p); break;
        case 3: out[i] = v.getUint16(p, le); break;
        case 8: out[i] = v.getInt16(p, le); break;
        case 4: case 13: out[i] = v.getUint32(p, le); break;
        case 9: out[i] = v.getInt32(p, le); break;
        case 5: out[i] = v.getUint32(p, le) / v.getUint32(p + 4, le); break;
        case 10: out[i] = v.getInt32(p, le) / v.getInt32(p + 4, le); break;
        case 11: out[i] = v.getFloat32(p, le); break;
        case 12: out[i] = v.getFloat64(p, le); break;
        case 16: case 18: out[i] = this.u64(p); break;
        default: out[i] = Number(v.getBigInt64(p, le)); break; // SLONG8
      }
    }
    return out;
  }

  /** The tag's single integer value, `fallback` when absent; refused unless an
   * integer within [min, max]. */
  integer(name: TagName, fallback: number | undefined, min: number, max: number): number {
    const values = this.numbers(name);
    if (!values) {
      if (fallback === undefined) fail('TIFF', `tag ${name} (${TAG[name]}) is missing`);
      return fallback;
    }
    const value = values[0]!;
    if (!Number.isInteger(value) || value < min || value > max)
      fail('TIFF', `tag ${name} (${TAG[name]}) is ${value}, expected an integer from ${min} to ${max}`);
    return value;
  }

  /** The tag's ASCII text, without its terminating NUL; undefined when absent. */
  text(name: TagName): string | undefined {
    const entry = this.entries.get(TAG[name]);
    if (!entry) return undefined;
    if (entry.type !== 2) fail('TIFF', `tag ${name} (${TAG[name]}) has type ${TYPE_NAME[entry.type]}, expected ASCII`);
    let s = '';
    for (let i = 0; i < entry.count; ++i) s += String.fromCharCode(this.bytes[entry.at + i]!);
    return s.replace(/\0[\s\S]*$/, '');
  }
}
