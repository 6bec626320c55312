/**
 * Lossless byte shuffling of doubles: byte k of every value is stored together,
 * so the similar sign and exponent bytes of nearby coordinates form long runs that
 * deflate compresses well (the trick of Blosc and HDF5's shuffle filter). Values
 * are written little-endian whatever the machine.
 */
export function shuffleDoubles(values: Float64Array): Uint8Array {
  const n = values.length;
  const le = new DataView(new ArrayBuffer(8));
  const out = new Uint8Array(8 * n);
  for (let i = 0; i < n; i++) {
    le.setFloat64(0, values[i]!, true);
    for (let b = 0; b < 8; b++) out[b * n + i] = le.getUint8(b);
  }
  return out;
}

export function unshuffleDoubles(shuffled: Uint8Array): Float64Array {
  if (shuffled.length % 8 !== 0) throw new Error('the point data is not a whole number of doubles');
  const n = shuffled.length / 8;
  const le = new DataView(new ArrayBuffer(8));
  const values = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    for (let b = 0; b < 8; b++) le.setUint8(b, shuffled[b * n + i]!);
    values[i] = le.getFloat64(0, true);
  }
  return values;
}

/** Coordinates x, y, z per point reordered as all x, all y, all z (and back). */
export function toColumns(xyz: Float64Array): Float64Array {
  const n = xyz.length / 3;
  const out = new Float64Array(xyz.length);
  for (let i = 0; i < n; i++) {
    out[i] = xyz[3 * i]!;
    out[n + i] = xyz[3 * i + 1]!;
    out[2 * n + i] = xyz[3 * i + 2]!;
  }
  return out;
}

export function fromColumns(columns: Float64Array): Float64Array {
  const n = columns.length / 3;
  const out = new Float64Array(columns.length);
  for (let i = 0; i < n; i++) {
    out[3 * i] = columns[i]!;
    out[3 * i + 1] = columns[n + i]!;
    out[3 * i + 2] = columns[2 * n + i]!;
  }
  return out;
}
