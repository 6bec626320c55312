// Mutations of the GIS fixtures for the loader fuzzer, each a pure function of its
// seed (mutate(seed) gives the same file every time, so a finding is replayed by
// its seed alone). Structural mutations set one field of the format (a TIFF
// directory entry's tag, type, count or value, one strip's offset or byte count;
// a LAS header field or VLR length) to a value from the edges of its range;
// the others flip, zero, truncate or splice bytes. Some structural mutations make
// the data missing or inconsistent for certain: `mustRefuse` says so.
import { readdirSync, readFileSync } from 'node:fs';

const root = new URL('../../../', import.meta.url).pathname;
const dir = `${root}tests/fixtures-gis`;
export const FIXTURES = readdirSync(dir)
  .filter((f) => /\.(tif|las|laz)$/.test(f))
  .sort()
  .map((name) => ({ name, bytes: new Uint8Array(readFileSync(`${dir}/${name}`)) }));

// A small fast PRNG (mulberry32) seeded per mutation.
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const edges = (len) => [0, 1, 2, 3, 7, 8, 12, 16, 255, 256, 4095, 4096, 0x7fff, 0x8000, 0xffff, 0x10000, 0xffffff, 0x1000005, 0x7fffffff, 0xffffffff, len - 1, len, len + 1, len >> 1];

function put(view, at, size, value, little) {
  if (at < 0 || at + size > view.byteLength) return;
  if (size === 1) view.setUint8(at, value & 0xff);
  else if (size === 2) view.setUint16(at, value & 0xffff, little);
  else if (size === 4) view.setUint32(at, value >>> 0, little);
  else view.setBigUint64(at, BigInt.asUintN(64, BigInt(Math.trunc(value))), little);
}

// The entries of a classic TIFF's first IFD: where each field is.
function tiffEntries(b) {
  const v = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const little = b[0] === 0x49;
  const first = v.getUint32(4, little);
  const count = v.getUint16(first, little);
  const entries = [];
  for (let i = 0; i < count; ++i) {
    const e = first + 2 + 12 * i;
    const tag = v.getUint16(e, little), type = v.getUint16(e + 2, little), n = v.getUint32(e + 4, little);
    const size = [0, 1, 1, 2, 4, 8, 1, 1, 2, 4, 8, 4, 8][type] ?? 0;
    const at = n * size <= 4 ? e + 8 : v.getUint32(e + 8, little);
    entries.push({ e, tag, type, n, size, at });
  }
  return { v, little, first, entries };
}

const RECORD_LENGTH = [20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67];
const DATA_TAGS = new Set([273, 279, 324, 325]); // strip/tile offsets and byte counts
const LAS_FIELDS = [
  // [offset, size, name]
  [24, 1, 'major'], [25, 1, 'minor'], [94, 2, 'header size'], [96, 4, 'point data offset'], [100, 4, 'VLR count'],
  [104, 1, 'point format'], [105, 2, 'record length'], [107, 4, 'point count'], [111, 4, 'returns'],
  [131, 8, 'x scale'], [139, 8, 'y scale'], [147, 8, 'z scale'], [155, 8, 'x offset'], [163, 8, 'y offset'], [171, 8, 'z offset'],
  [247, 8, 'point count (1.4)'],
];

/** The mutated file of `seed`: { name, bytes, what, mustRefuse }. */
export function mutate(seed) {
  const r = rng(seed);
  const pick = (a) => a[Math.floor(r() * a.length)];
  const fixture = FIXTURES[seed % FIXTURES.length];
  const b = fixture.bytes.slice();
  const len = b.length;
  const tiff = fixture.name.endsWith('.tif');
  const kind = r();
  let what;
  let mustRefuse = false;
  if (kind < 0.45) {
    if (tiff) {
      const { v, little, entries } = tiffEntries(b);
      const entry = pick(entries);
      const field = pick(['tag', 'type', 'count', 'value', 'element', 'element', 'delete', 'zero-count']);
      const value = r() < 0.8 ? pick(edges(len)) : Math.floor(r() * 2 ** 32);
      if (field === 'tag') put(v, entry.e, 2, value, little);
      else if (field === 'type') put(v, entry.e + 2, 2, value & 0x1f, little);
      else if (field === 'count') put(v, entry.e + 4, 4, value, little);
      else if (field === 'value') put(v, entry.e + 8, 4, value, little);
      else if (field === 'delete') put(v, entry.e, 2, 65000, little); // (an unknown tag: the entry is gone)
      else if (field === 'zero-count' && DATA_TAGS.has(entry.tag)) {
        // one strip's or tile's byte count set to 0: its data are missing
        const counts = entries.find((x) => x.tag === (entry.tag === 273 || entry.tag === 279 ? 279 : 325));
        if (counts) put(v, counts.at + counts.size * Math.floor(r() * counts.n), counts.size, 0, little);
      } else {
        const k = Math.floor(r() * entry.n);
        if (entry.size && entry.at + (k + 1) * entry.size <= len) put(v, entry.at + k * entry.size, Math.min(entry.size, 4), value, little);
      }
      what = `TIFF tag ${entry.tag} ${field} = ${value}`;
      // Without its offsets or byte counts, a raster's data are missing.
      if ((field === 'delete' || field === 'tag') && DATA_TAGS.has(entry.tag) && value !== entry.tag) mustRefuse = true;
      if (field === 'zero-count' && DATA_TAGS.has(entry.tag)) mustRefuse = true;
      // Data read under another compression are never the raster's samples.
      if (entry.tag === 259 && field === 'value') {
        const codec = (c) => (c === 32946 ? 8 : c);
        if (codec(value & 0xffff) !== codec(fixture.bytes[entry.e + 8] | (fixture.bytes[entry.e + 9] << 8))) mustRefuse = true;
      }
    } else {
      const v = new DataView(b.buffer);
      const [at, size, name] = pick(LAS_FIELDS);
      let value;
      if (size === 8 && at < 247) value = pick([0, NaN, Infinity, -Infinity, 1e-300, 1e300, -0.01]);
      else value = r() < 0.8 ? pick(edges(len)) : Math.floor(r() * 2 ** 32);
      if (size === 8 && at < 247) v.setFloat64(at, value, true);
      else put(v, at, size, value, true);
      what = `LAS ${name} = ${value}`;
      const headerSize = fixture.bytes[94] | (fixture.bytes[95] << 8);
      if (name === 'point data offset' && value < headerSize) mustRefuse = true;
      const recordLength = fixture.bytes[105] | (fixture.bytes[106] << 8);
      if (name === 'record length' && value < RECORD_LENGTH[fixture.bytes[104] & 0x3f]) mustRefuse = true;
      if (name === 'point format') {
        const format = value & 0x3f;
        if (format > 10 || RECORD_LENGTH[format] > recordLength || (value & 0xc0 ? 1 : 0) !== (fixture.bytes[104] & 0xc0 ? 1 : 0)) mustRefuse = true;
      }
      if (size === 8 && at >= 131 && at < 155 && !(Number.isFinite(value) && value !== 0)) mustRefuse = true;
    }
  } else if (kind < 0.75) {
    const flips = 1 + Math.floor(r() * 8);
    for (let i = 0; i < flips; ++i) b[Math.floor(r() * len)] = r() < 0.3 ? pick([0, 255]) : Math.floor(r() * 256);
    what = `${flips} random bytes`;
  } else if (kind < 0.9) {
    const cut = Math.floor(r() * len);
    what = `truncated at ${cut}`;
    return { name: fixture.name, bytes: b.subarray(0, cut), what, mustRefuse };
  } else {
    const from = Math.floor(r() * len), to = Math.floor(r() * len), n = Math.floor(r() * 64);
    const spliced = new Uint8Array(len + n);
    spliced.set(b.subarray(0, to));
    spliced.set(b.subarray(from, from + n), to);
    spliced.set(b.subarray(to), to + Math.min(n, len - from));
    what = `${n} bytes from ${from} inserted at ${to}`;
    return { name: fixture.name, bytes: spliced.subarray(0, to + Math.min(n, len - from) + (len - to)), what, mustRefuse };
  }
  return { name: fixture.name, bytes: b, what, mustRefuse };
}
