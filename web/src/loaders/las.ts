// LAS and LAZ point clouds as points: the ground class (2) by default, every
// class on request. The header is checked first (las/header.ts); LAS records are
// read here (a fixed layout); LAZ is decompressed by laz-perf (las/laz.ts), loaded
// only for LAZ. Output grows with the points decoded, never with a count the
// file has not shown it holds.
import { fail } from './fail.js';
import { readHeader, type Header } from './las/header.js';
import type { PointCloud } from './types.js';

export interface LASOptions {
  /** 'ground' (class 2, the default) or 'all'. A file with no ground point is read whole, with a warning. */
  classes?: 'ground' | 'all';
}

const GROUND = 2;

// The classification of the record at `at` (formats 6 to 10 keep it whole at byte 16).
const classOf = (format: number, view: DataView, at: number) =>
  format >= 6 ? view.getUint8(at + 16) : view.getUint8(at + 15) & 0x1f;

/** x, y, z triples and the record each came from, appended one at a time into
 * doubling buffers. */
class Triples {
  private data: Float64Array;
  private records: Uint32Array;
  length = 0;
  constructor(capacity: number) {
    this.data = new Float64Array(3 * Math.max(1, capacity));
    this.records = new Uint32Array(Math.max(1, capacity));
  }
  push(record: number, x: number, y: number, z: number) {
    if (this.length === this.records.length) {
      const grown = new Float64Array(2 * this.data.length);
      grown.set(this.data);
      this.data = grown;
      const more = new Uint32Array(2 * this.records.length);
      more.set(this.records);
      this.records = more;
    }
    this.records[this.length] = record;
    this.data[3 * this.length] = x;
    this.data[3 * this.length + 1] = y;
    this.data[3 * this.length++ + 2] = z;
  }
  get xyz(): Float64Array {
    return this.data.slice(0, 3 * this.length);
  }
  /** PointCloud.origin of these points. */
  get origin(): (i: number) => string {
    const records = this.records;
    return (i) => `point record ${records[i]}`;
  }
}

async function forEachRecord(bytes: Uint8Array, h: Header, visit: (view: DataView, at: number) => void): Promise<void> {
  if (h.compressed) {
    const { forEachCompressedRecord } = await import('./las/laz.js');
    return forEachCompressedRecord(bytes, h, visit);
  }
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let i = 0; i < h.count; ++i) visit(view, h.offset + i * h.recordLength);
}

export async function readLAS(bytes: Uint8Array, options: LASOptions = {}): Promise<PointCloud> {
  const classes = options.classes ?? 'ground';
  if (classes !== 'ground' && classes !== 'all') fail('LAS', `classes must be 'ground' or 'all', got '${String(classes)}'`);
  const h = readHeader(bytes);
  // An uncompressed file holds its count (the header check): room for all of them.
  // LAZ: room for what the compressed bytes could hold at a byte a point, grown as decoded.
  const room = h.compressed ? Math.min(h.count, bytes.length) : h.count;
  const all = new Triples(room);
  const ground = new Triples(classes === 'ground' ? Math.min(room, 1024) : 0);
  let record = 0;
  await forEachRecord(bytes, h, (view, at) => {
    const x = view.getInt32(at, true) * h.scale[0] + h.origin[0];
    const y = view.getInt32(at + 4, true) * h.scale[1] + h.origin[1];
    const z = view.getInt32(at + 8, true) * h.scale[2] + h.origin[2];
    all.push(record, x, y, z);
    if (classes === 'ground' && classOf(h.format, view, at) === GROUND) ground.push(record, x, y, z);
    ++record;
  });
  const warnings: string[] = [];
  const crs = h.crs ? { crs: h.crs } : {};
  const n = all.length;
  const g = ground.length;
  if (classes === 'ground' && g === 0) warnings.push(`no point is classified ground (class 2): read all ${n} points`);
  if (classes === 'all' || g === 0) return { xyz: all.xyz, ...crs, warnings, origin: all.origin };
  if (g < n) warnings.push(`read ${g} ground points (class 2) of ${n}; --classes all reads every point`);
  return { xyz: ground.xyz, ...crs, warnings, origin: ground.origin };
}
