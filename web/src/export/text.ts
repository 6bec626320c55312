// Text files built in parts: a TIN of a million points as GeoJSON is longer than
// the longest string a JavaScript engine allows (about 512 MiB in V8), so the text
// writers yield parts of a few thousand lines, which can be written or encoded one
// by one without ever holding the whole file.

const LINES_PER_PART = 4096;

/** Lines collected into one part. */
export class LineBatch {
  #lines: string[] = [];

  /** Adds a line; true when the batch is full and should be taken. */
  add(line: string): boolean {
    this.#lines.push(line);
    return this.#lines.length >= LINES_PER_PART;
  }

  /** The lines so far, each ended by '\n', as one string; empties the batch. */
  take(): string {
    const part = this.#lines.length > 0 ? `${this.#lines.join('\n')}\n` : '';
    this.#lines = [];
    return part;
  }
}

/** The parts (text as UTF-8) as one array of bytes. */
export function concatParts(parts: Iterable<string | Uint8Array>): Uint8Array {
  const encoder = new TextEncoder();
  const encoded = Array.from(parts, (p) => (typeof p === 'string' ? encoder.encode(p) : p));
  const out = new Uint8Array(encoded.reduce((s, b) => s + b.length, 0));
  let at = 0;
  for (const b of encoded) {
    out.set(b, at);
    at += b.length;
  }
  return out;
}
