// Text files built in parts: a TIN of a million points as GeoJSON is longer than
// the longest string a JavaScript engine allows (about 512 MiB in V8), so writers
// produce parts of a few thousand lines and exportMesh encodes them one by one.

const LINES_PER_PART = 4096;

/** Collects lines into parts. */
export class TextParts {
  readonly parts: string[] = [];
  #lines: string[] = [];

  line(text: string): void {
    this.#lines.push(text);
    if (this.#lines.length === LINES_PER_PART) this.#flush();
  }

  /** The parts, every line ended by '\n'. */
  done(): string[] {
    this.#flush();
    return this.parts;
  }

  #flush(): void {
    if (this.#lines.length > 0) this.parts.push(`${this.#lines.join('\n')}\n`);
    this.#lines = [];
  }
}

/** The parts as UTF-8 bytes. */
export function encodeParts(parts: readonly string[]): Uint8Array {
  const encoder = new TextEncoder();
  const encoded = parts.map((p) => encoder.encode(p));
  const out = new Uint8Array(encoded.reduce((s, b) => s + b.length, 0));
  let at = 0;
  for (const b of encoded) {
    out.set(b, at);
    at += b.length;
  }
  return out;
}
