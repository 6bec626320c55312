// LAZ point records through laz-perf (LASzip in wasm). One laz-perf module per
// process, made on first use; each file gets its own LASZip reader and buffers,
// freed when the file is read. The module's Node glue registers process-wide
// handlers (uncaughtException, unhandledRejection) that would change how the
// host process fails; they are removed as soon as the module is made. A module
// that failed while decoding may be left inconsistent, so it is dropped.
import { fail, rethrow } from '../fail.js';
import type { Header } from './header.js';

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

let module: Promise<LazModule> | undefined;

async function lazPerf(): Promise<LazModule> {
  if (!module) {
    module = (async () => {
      const { createLazPerf } = (await import('laz-perf')) as unknown as { createLazPerf: () => Promise<LazModule> };
      const host = typeof process === 'object' && typeof process.listeners === 'function' ? process : undefined;
      const events = ['uncaughtException', 'unhandledRejection'] as const;
      const before = host ? events.map((e) => new Set(host.listeners(e))) : [];
      try {
        return await createLazPerf();
      } finally {
        if (host)
          events.forEach((e, i) => {
            for (const listener of host.listeners(e)) if (!before[i]!.has(listener)) host.removeListener(e, listener as never);
          });
      }
    })();
    module.catch(() => (module = undefined));
  }
  return module;
}

// The chunk table's size, where LASzip writes one (its offset is the first 8
// bytes of the point data; -1 means it is in the file's last 8 bytes). With
// chunks of a fixed size, every chunk but the last is full, so the header's
// count must lie in ((chunks - 1) * size, chunks * size].
function checkChunks(bytes: Uint8Array, h: Header): void {
  const v = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const n = bytes.length;
  if (h.offset + 8 > n) fail('LAZ', `the point data at byte ${h.offset} end before the chunk table's offset`);
  let table = Number(v.getBigInt64(h.offset, true));
  if (table === -1 && n >= 8) table = Number(v.getBigInt64(n - 8, true));
  if (!(table >= h.offset + 8 && table + 8 <= n))
    fail('LAZ', `the chunk table's offset is ${table}, outside the point data (bytes ${h.offset + 8} to ${n - 8})`);
  const chunks = v.getUint32(table + 4, true);
  const size = h.chunkSize!;
  if (chunks === 0) fail('LAZ', 'the chunk table lists no chunks');
  if (size !== 0xffffffff && size > 0 && !(h.count > (chunks - 1) * size && h.count <= chunks * size))
    fail('LAZ', `the header promises ${h.count} points; the chunk table's ${chunks} chunks of ${size} points hold ${(chunks - 1) * size + 1} to ${chunks * size}`);
}

/** Calls visit(view, at) for each of the header's point records. */
export async function forEachCompressedRecord(bytes: Uint8Array, h: Header, visit: (view: DataView, at: number) => void): Promise<void> {
  checkChunks(bytes, h);
  const laz = await lazPerf();
  let file = 0;
  let point = 0;
  let zip: InstanceType<LazModule['LASZip']> | undefined;
  let i = 0;
  try {
    file = laz._malloc(bytes.length);
    laz.HEAPU8.set(bytes, file);
    zip = new laz.LASZip();
    zip.open(file, bytes.length);
    if (zip.getPointLength() < h.recordLength) fail('LAZ', `LASzip decodes records of ${zip.getPointLength()} bytes; the header says ${h.recordLength}`);
    point = laz._malloc(zip.getPointLength());
    let view = new DataView(laz.HEAPU8.buffer);
    for (; i < h.count; ++i) {
      zip.getPoint(point);
      if (view.buffer !== laz.HEAPU8.buffer) view = new DataView(laz.HEAPU8.buffer); // (the heap grew)
      visit(view, point);
    }
  } catch (e) {
    module = undefined; // (a trap or an exception inside LASzip may leave the module inconsistent)
    rethrow('LAZ', `the compressed points are corrupt: LASzip failed at point ${i} of ${h.count}`, /^\d+\b/.test(e instanceof Error ? e.message : String(e)) ? undefined : e); // (laz-perf's C++ exceptions arrive as a bare pointer)
  } finally {
    try {
      zip?.delete();
      if (point) laz._free(point);
      if (file) laz._free(file);
    } catch {
      module = undefined;
    }
  }
}
