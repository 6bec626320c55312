// LAS and LAZ point clouds as points: the ground class (2) by default, every
// class on request. LAS records are read here (a fixed layout); LAZ is
// decompressed by the laz-perf package (LASzip in wasm), loaded only for LAZ.
import type { PointCloud } from './types.js';

export interface LASOptions {
  /** 'ground' (class 2, the default) or 'all'. A file with no ground point is read whole, with a warning. */
  classes?: 'ground' | 'all';
}

const GROUND = 2;

interface Header {
  format: number; // point data record format, without the compression bits
  compressed: boolean;
  recordLength: number;
  offset: number; // to the first point
  count: number;
  scale: [number, number, number];
  origin: [number, number, number];
  crs?: string;
}

function readHeader(bytes: Uint8Array): Header {
  if (bytes.length < 227) throw new Error('LAS: the file is shorter than a LAS header');
  const v = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const minor = bytes[25]!;
  const headerSize = v.getUint16(94, true);
  const formatByte = bytes[104]!;
  let count = v.getUint32(107, true);
  if (minor >= 4 && headerSize >= 375 && count === 0) count = Number(v.getBigUint64(247, true));
  const h: Header = {
    format: formatByte & 0x3f,
    compressed: (formatByte & 0xc0) !== 0,
    recordLength: v.getUint16(105, true),
    offset: v.getUint32(96, true),
    count,
    scale: [v.getFloat64(131, true), v.getFloat64(139, true), v.getFloat64(147, true)],
    origin: [v.getFloat64(155, true), v.getFloat64(163, true), v.getFloat64(171, true)],
  };
  if (h.format > 10) throw new Error(`LAS: point data record format ${h.format} is not a LAS format (0 to 10)`);
  if (!h.scale.every((s) => Number.isFinite(s) && s !== 0) || !h.origin.every(Number.isFinite))
    throw new Error(`LAS: the header's scale (${h.scale.join(', ')}) or offset (${h.origin.join(', ')}) is not usable`);
  // The CRS: an EPSG code in the GeoTIFF key directory VLR (LASF_Projection, record 34735).
  let at = headerSize;
  const vlrs = v.getUint32(100, true);
  for (let i = 0; i < vlrs && at + 54 <= bytes.length; ++i) {
    const user = String.fromCharCode(...bytes.subarray(at + 2, at + 18)).replace(/\0.*$/s, '');
    const record = v.getUint16(at + 18, true);
    const length = v.getUint16(at + 20, true);
    const data = at + 54;
    if (user === 'LASF_Projection' && record === 34735 && data + length <= bytes.length) {
      const keys = v.getUint16(data + 6, true);
      for (let k = 0; k < keys; ++k) {
        const e = data + 8 + 8 * k;
        if (e + 8 > data + length) break;
        const id = v.getUint16(e, true);
        const location = v.getUint16(e + 2, true);
        const value = v.getUint16(e + 6, true);
        if (location === 0 && (id === 3072 || (id === 2048 && !h.crs)) && value > 0 && value < 32767) h.crs = `EPSG:${value}`;
      }
    }
    at = data + length;
  }
  return h;
}

// The classification of the record at `at` (formats 6 to 10 keep it whole at byte 16).
const classOf = (format: number, view: DataView, at: number) =>
  format >= 6 ? view.getUint8(at + 16) : view.getUint8(at + 15) & 0x1f;

interface LazModule {
  HEAPU8: Uint8Array;
  _malloc(size: number): number;
  _free(ptr: number): void;
  LASZip: new () => {
    open(ptr: number, length: number): void;
    getPoint(ptr: number): void;
    getCount(): number;
    getPointLength(): number;
    delete(): void;
  };
}

// Calls visit(view, at) for each of the header's point records, decompressing LAZ.
async function forEachRecord(bytes: Uint8Array, h: Header, visit: (view: DataView, at: number) => void) {
  if (!h.compressed) {
    if (h.offset + h.count * h.recordLength > bytes.length)
      throw new Error(`LAS: the header promises ${h.count} points of ${h.recordLength} bytes; the file is shorter`);
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    for (let i = 0; i < h.count; ++i) visit(view, h.offset + i * h.recordLength);
    return;
  }
  const { createLazPerf } = (await import('laz-perf')) as unknown as { createLazPerf: () => Promise<LazModule> };
  const laz = await createLazPerf();
  const file = laz._malloc(bytes.length);
  const zip = new laz.LASZip();
  let point = 0;
  try {
    laz.HEAPU8.set(bytes, file);
    zip.open(file, bytes.length);
    if (zip.getCount() < h.count) throw new Error(`the header promises ${h.count} points, the data hold ${zip.getCount()}`);
    point = laz._malloc(zip.getPointLength());
    let view = new DataView(laz.HEAPU8.buffer);
    for (let i = 0; i < h.count; ++i) {
      zip.getPoint(point);
      if (view.buffer !== laz.HEAPU8.buffer) view = new DataView(laz.HEAPU8.buffer); // (the heap grew)
      visit(view, point);
    }
  } catch (e) {
    throw new Error(`LAZ: cannot decompress: ${e instanceof Error ? e.message : String(e)}`);
  } finally {
    zip.delete();
    if (point) laz._free(point);
    laz._free(file);
  }
}

export async function readLAS(bytes: Uint8Array, options: LASOptions = {}): Promise<PointCloud> {
  const classes = options.classes ?? 'ground';
  if (classes !== 'ground' && classes !== 'all') throw new Error(`LAS: classes must be 'ground' or 'all', got '${String(classes)}'`);
  const h = readHeader(bytes);
  const all = new Float64Array(3 * h.count);
  const ground = new Float64Array(classes === 'ground' ? 3 * h.count : 0);
  let n = 0;
  let g = 0;
  await forEachRecord(bytes, h, (view, at) => {
    const x = view.getInt32(at, true) * h.scale[0] + h.origin[0];
    const y = view.getInt32(at + 4, true) * h.scale[1] + h.origin[1];
    const z = view.getInt32(at + 8, true) * h.scale[2] + h.origin[2];
    all[3 * n] = x;
    all[3 * n + 1] = y;
    all[3 * n++ + 2] = z;
    if (classes === 'ground' && classOf(h.format, view, at) === GROUND) {
      ground[3 * g] = x;
      ground[3 * g + 1] = y;
      ground[3 * g++ + 2] = z;
    }
  });
  const warnings: string[] = [];
  if (classes === 'ground' && g === 0) warnings.push(`no point is classified ground (class 2): read all ${n} points`);
  if (classes === 'all' || g === 0) return { xyz: all, ...(h.crs ? { crs: h.crs } : {}), warnings };
  if (g < n) warnings.push(`read ${g} ground points (class 2) of ${n}; --classes all reads every point`);
  return { xyz: ground.slice(0, 3 * g), ...(h.crs ? { crs: h.crs } : {}), warnings };
}
