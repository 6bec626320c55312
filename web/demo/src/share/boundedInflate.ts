import { Inflate } from 'fflate';

/** Raw inflate that gives up once the output would exceed maxBytes, so a small
 * malicious link cannot expand into gigabytes. */
export function boundedInflate(data: Uint8Array, maxBytes: number): Uint8Array {
  const parts: Uint8Array[] = [];
  let size = 0;
  const inflate = new Inflate((chunk) => {
    size += chunk.length;
    if (size > maxBytes) throw new RangeError('too large');
    parts.push(chunk);
  });
  const step = 1024; // at most ~1 MB of output per pushed kilobyte
  for (let i = 0; i < data.length; i += step) {
    inflate.push(data.subarray(i, i + step), i + step >= data.length);
  }
  if (data.length === 0) inflate.push(new Uint8Array(0), true);
  const out = new Uint8Array(size);
  let offset = 0;
  for (const p of parts) {
    out.set(p, offset);
    offset += p.length;
  }
  return out;
}
