// TIFF's LZW (TIFF 6.0, Section 13): codes of 9 to 12 bits, most significant bit
// first, 256 clears the table, 257 ends the data, and the code width grows one
// code early (when the table is about to fill the current width). Every code is
// checked against the table before it is used, the table never grows past 4096
// entries, and the output never past the chunk it decodes: a corrupted stream is
// an error, never a loop or an allocation larger than the chunk.
const CLEAR = 256;
const END = 257;
const FIRST = 258;
const LIMIT = 4096;

/** Decodes one LZW chunk into at most `capacity` bytes. Throws on a code that is
 * not in the table, on a table that overflows without a clear, and on data that
 * end before the chunk is full without an end code. */
export function decodeLZW(input: Uint8Array, capacity: number): Uint8Array {
  const prefix = new Uint16Array(LIMIT);
  const suffix = new Uint8Array(LIMIT);
  const first = new Uint8Array(LIMIT); // each string's first byte
  const length = new Uint16Array(LIMIT);
  for (let i = 0; i < 256; ++i) {
    suffix[i] = first[i] = i;
    length[i] = 1;
  }
  const out = new Uint8Array(capacity);
  const bits = input.length * 8;
  let n = 0;
  let at = 0; // in bits
  let width = 9;
  let next = FIRST;
  let previous = -1;
  // Writes the string of `code` at out[n..], as much of it as fits.
  const write = (code: number) => {
    const end = n + length[code]!;
    for (let p = end - 1, c = code; p >= n; --p, c = prefix[c]!) if (p < capacity) out[p] = suffix[c]!;
    n = Math.min(end, capacity);
  };
  while (n < capacity) {
    if (at + width > bits) throw new Error(`LZW data end after ${n} of ${capacity} bytes, without an end code`);
    // (width <= 12 bits starting anywhere in a byte spans at most three bytes)
    const byte = at >>> 3;
    const word = (input[byte]! << 16) | ((input[byte + 1] ?? 0) << 8) | (input[byte + 2] ?? 0);
    const code = (word >>> (24 - (at & 7) - width)) & ((1 << width) - 1);
    at += width;
    if (code === END) break;
    if (code === CLEAR) {
      width = 9;
      next = FIRST;
      previous = -1;
      continue;
    }
    if (previous < 0) {
      if (code > 255) throw new Error(`LZW code ${code} where a byte (below 256) must follow a clear`);
      out[n++] = code;
      previous = code;
      continue;
    }
    if (code > next || (code === next && next >= LIMIT)) throw new Error(`LZW code ${code} is not in the table (of ${next})`);
    if (next >= LIMIT) throw new Error('LZW table full without a clear code');
    // code === next: the string of the previous code and its own first byte.
    const head = code < next ? first[code]! : first[previous]!;
    prefix[next] = previous;
    suffix[next] = head;
    first[next] = first[previous]!;
    length[next] = length[previous]! + 1;
    ++next;
    write(code);
    if (next + 1 >= 1 << width && width < 12) ++width;
    previous = code;
  }
  return n === capacity ? out : out.subarray(0, n);
}
