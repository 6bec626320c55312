// The band of a checked raster (raster.ts) decoded chunk by chunk: each chunk's
// bytes decompressed (geotiff's decoders; LZW bounded, lzw.ts; a ZSTD frame's
// declared size checked first, zstdFrame.ts), its predictor
// undone, its decoded length compared with the size its cells need, and its
// samples copied into one height per cell, NaN where the cell has no data.
import { fail, rethrow } from '../fail.js';
import { decodeLZW } from './lzw.js';
import { checkZstdFrame } from './zstdFrame.js';
import type { Raster } from './raster.js';

interface Decoder {
  decode(buffer: ArrayBuffer): Promise<ArrayBufferLike>;
}

// One decoder per chunk height (a short last strip has its own, so that the
// predictor runs over its rows only).
async function decoderFor(r: Raster, rows: number): Promise<Decoder> {
  const geotiff = await import('geotiff');
  const parameters = {
    tileWidth: r.chunkWidth,
    tileHeight: rows,
    planarConfiguration: r.planar,
    bitsPerSample: r.planar === 2 ? [r.bitsPerSample[0]!] : r.bitsPerSample,
    predictor: r.predictor,
    samplesPerPixel: r.samplesPerPixel,
  };
  if (r.compression === 5) {
    // geotiff's decoder interface (its predictor applied after decodeBlock) over
    // decodeLZW, bounded by the chunk's size.
    const capacity = r.chunkWidth * rows * r.pixelBytes;
    class LZWDecoder extends geotiff.BaseDecoder {
      override decodeBlock(buffer: ArrayBufferLike): ArrayBuffer {
        return decodeLZW(new Uint8Array(buffer), capacity).slice().buffer;
      }
    }
    return new LZWDecoder(parameters);
  }
  return geotiff.getDecoder(r.compression, parameters);
}

function sampleReader(r: Raster, view: DataView): (at: number) => number {
  const le = r.little || r.predictor === 3; // (the floating point predictor leaves little-endian samples)
  if (r.sampleFormat === 3) return r.sampleBytes === 4 ? (at) => view.getFloat32(at, le) : (at) => view.getFloat64(at, le);
  const signed = r.sampleFormat === 2;
  switch (r.sampleBytes) {
    case 1: return signed ? (at) => view.getInt8(at) : (at) => view.getUint8(at);
    case 2: return signed ? (at) => view.getInt16(at, le) : (at) => view.getUint16(at, le);
    default: return signed ? (at) => view.getInt32(at, le) : (at) => view.getUint32(at, le);
  }
}

/** The band's heights, row by row from the top; NaN for NODATA and non-finite samples. */
export async function decodeRaster(bytes: Uint8Array, r: Raster): Promise<Float64Array> {
  const z = new Float64Array(r.width * r.height);
  const decoders = new Map<number, Decoder>();
  const kind = r.tiled ? 'tile' : 'strip';
  for (let i = 0; i < r.chunks.length; ++i) {
    const { offset, byteCount, rows } = r.chunks[i]!;
    const top = Math.floor(i / r.chunksAcross) * r.chunkHeight;
    const left = (i % r.chunksAcross) * r.chunkWidth;
    const need = r.chunkWidth * rows * r.pixelBytes;
    const rowsHere = Math.min(rows, r.height - top);
    const colsHere = Math.min(r.chunkWidth, r.width - left);
    if (byteCount === 0) {
      for (let y = 0; y < rowsHere; ++y) z.fill(NaN, (top + y) * r.width + left, (top + y) * r.width + left + colsHere);
      continue; // (a sparse chunk: NODATA)
    }
    if (r.compression === 50000) checkZstdFrame(bytes.subarray(offset, offset + byteCount), r.chunkWidth * r.chunkHeight * r.pixelBytes, `${kind} ${i}`);
    let decoded: ArrayBufferLike;
    try {
      let decoder = decoders.get(rows);
      if (!decoder) decoders.set(rows, (decoder = await decoderFor(r, rows)));
      const stored = r.compression === 1 ? Math.min(byteCount, need) : byteCount; // (raw: padding after the cells ignored)
      decoded = await decoder.decode(bytes.slice(offset, offset + stored).buffer);
    } catch (e) {
      rethrow('GeoTIFF', `${kind} ${i}: its ${r.compressionName} data cannot be decoded`, e);
    }
    // Exactly the chunk's cells (a short last strip may also be stored at full
    // height): any other length means the data are not what the header says.
    const full = r.chunkWidth * r.chunkHeight * r.pixelBytes;
    if (decoded.byteLength !== need && decoded.byteLength !== full)
      fail('GeoTIFF', `${kind} ${i}: its ${r.compressionName} data decode to ${decoded.byteLength} bytes, expected ${need} for its ${r.chunkWidth} x ${rows} cells`);
    const read = sampleReader(r, new DataView(decoded));
    for (let y = 0; y < rowsHere; ++y) {
      for (let x = 0; x < colsHere; ++x) {
        const h = read((y * r.chunkWidth + x) * r.pixelBytes + r.sampleOffset);
        z[(top + y) * r.width + left + x] = Number.isFinite(h) && h !== r.nodata ? h : NaN;
      }
    }
  }
  return z;
}
