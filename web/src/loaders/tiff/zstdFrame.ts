// A ZSTD frame's header (RFC 8878, Section 3.1.1), checked before the frame is
// handed to the decoder, which allocates whatever size the header declares: the
// magic number, and a declared content size no larger than the chunk.
import { fail } from '../fail.js';

const MAGIC = 0xfd2fb528;

export function checkZstdFrame(frame: Uint8Array, capacity: number, where: string): void {
  const v = new DataView(frame.buffer, frame.byteOffset, frame.byteLength);
  if (frame.length < 6 || v.getUint32(0, true) !== MAGIC) fail('GeoTIFF', `${where}: its data are flagged ZSTD but do not start a ZSTD frame`);
  const descriptor = frame[4]!;
  const single = (descriptor >> 5) & 1;
  const sizeBytes = [single, 2, 4, 8][descriptor >> 6]!;
  const at = 5 + (single ? 0 : 1) + [0, 1, 2, 4][descriptor & 3]!;
  if (!sizeBytes) return; // (no declared size: the decoder grows its output as it decodes)
  if (at + sizeBytes > frame.length) fail('GeoTIFF', `${where}: its ZSTD frame header is cut short`);
  const size =
    sizeBytes === 1 ? v.getUint8(at) : sizeBytes === 2 ? v.getUint16(at, true) + 256 : sizeBytes === 4 ? v.getUint32(at, true) : Number(v.getBigUint64(at, true));
  if (size > capacity) fail('GeoTIFF', `${where}: its ZSTD frame declares ${size} bytes, more than its cells' ${capacity}`);
}
