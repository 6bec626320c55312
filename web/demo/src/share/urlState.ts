import { deflateSync } from 'fflate';
import { OBJECTIVE_IDS, type Method, type ObjectiveId } from 'hodt';
import { isOrder, METHODS, VIEW_MODES, type ViewMode } from '../app/settings.ts';
import { isTerrainKind, TERRAIN_KINDS, type TerrainKind } from '../terrains/kinds.ts';
import { fromBase64Url, toBase64Url } from './base64url.ts';
import { boundedInflate } from './boundedInflate.ts';
import { fromColumns, shuffleDoubles, toColumns, unshuffleDoubles } from './byteShuffle.ts';

/**
 * The whole page state in the URL hash: `#v1=<base64url>`, the raw deflate of
 *   u32 (little-endian) length L of a JSON header,
 *   L bytes of UTF-8 JSON {n, objective, method, epsilon, order, view, source?,
 *     maxEdge?, exaggeration?} (order, maxEdge and exaggeration were added
 *     later: links without them mean order 1, no domain, automatic heights),
 *   24 n bytes: the 3n coordinates as doubles, by columns (all x, all y, all z),
 *   byte-shuffled.
 * The doubles are the exact bits of the points, so the link reproduces the exact
 * triangulation.
 */
export interface SharedState {
  points: Float64Array;
  objective: ObjectiveId;
  method: Method;
  epsilon: number;
  /** Order k of the Delaunay triangulations searched (1: first order). */
  order: number;
  /** The domain (Terrain.maxEdge), null for none. */
  maxEdge: number | null;
  view: ViewMode;
  /** The 3D view's height exaggeration, null for the automatic one (from the
   * points' extent and relief). */
  exaggeration: number | null;
  /** Where the points came from, for the terrain controls (optional). */
  source: { kind: TerrainKind; count: number; seed: number } | null;
}

export const HASH_VERSION = 'v1';
/** Longer hashes are refused: browsers and chat apps cut URLs around 2 MB. */
export const MAX_HASH_CHARS = 2_000_000;
export const MAX_POINTS = 20_000;

export class LinkError extends Error {
  override name = 'LinkError';
}

export function encodeState(s: SharedState): string {
  const header = new TextEncoder().encode(
    JSON.stringify({
      n: s.points.length / 3,
      objective: s.objective,
      method: s.method,
      epsilon: s.epsilon,
      order: s.order,
      view: s.view,
      ...(s.source ? { source: s.source } : {}),
      ...(s.maxEdge !== null ? { maxEdge: s.maxEdge } : {}),
      ...(s.exaggeration !== null ? { exaggeration: s.exaggeration } : {}),
    }),
  );
  const coords = shuffleDoubles(toColumns(s.points));
  const raw = new Uint8Array(4 + header.length + coords.length);
  new DataView(raw.buffer).setUint32(0, header.length, true);
  raw.set(header, 4);
  raw.set(coords, 4 + header.length);
  return `#${HASH_VERSION}=${toBase64Url(deflateSync(raw, { level: 9 }))}`;
}

/** Null for an empty hash; throws LinkError with a message for a user (and
 * nothing else, whatever the hash holds). */
export function decodeState(hash: string): SharedState | null {
  const body = hash.replace(/^#/, '');
  if (body === '') return null;
  if (body.length > MAX_HASH_CHARS) {
    throw new LinkError(`the link is too long (${body.length.toLocaleString('en')} characters; at most ${MAX_HASH_CHARS.toLocaleString('en')})`);
  }
  const eq = body.indexOf('=');
  const version = eq < 0 ? '' : body.slice(0, eq);
  if (!/^v\d+$/.test(version)) throw new LinkError('the link has no state in it (expected #v1=…)');
  if (version !== HASH_VERSION) throw new LinkError(`the link is format ${version}; this page reads ${HASH_VERSION}`);

  let compressed: Uint8Array;
  try {
    compressed = fromBase64Url(body.slice(eq + 1));
  } catch (e) {
    throw new LinkError(`the link cannot be read: ${(e as Error).message}`);
  }
  let raw: Uint8Array;
  try {
    raw = boundedInflate(compressed, 4 + 65536 + 24 * MAX_POINTS);
  } catch (e) {
    const why = e instanceof RangeError ? `it holds more than ${MAX_POINTS.toLocaleString('en')} points` : 'its data is damaged';
    throw new LinkError(`the link cannot be read: ${why}`);
  }
  if (raw.length < 4) throw new LinkError('the link cannot be read: its data is truncated');
  const length = new DataView(raw.buffer, raw.byteOffset).getUint32(0, true);
  if (length > 65536 || 4 + length > raw.length) throw new LinkError('the link cannot be read: its header is damaged');
  let parsed: unknown;
  try {
    parsed = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(raw.subarray(4, 4 + length)));
  } catch {
    throw new LinkError('the link cannot be read: its header is not valid JSON');
  }
  // JSON.parse gives null, arrays and bare values as readily as objects.
  if (parsed === null || typeof parsed !== 'object' || Array.isArray(parsed)) {
    throw new LinkError(`the link cannot be read: its header is ${shown(parsed)}, expected an object`);
  }
  const header = parsed as Record<string, unknown>;
  const n = header.n;
  if (typeof n !== 'number' || !Number.isInteger(n) || n < 3 || n > MAX_POINTS) {
    throw new LinkError(`the link cannot be read: bad point count ${shown(n)}`);
  }
  const coords = raw.subarray(4 + length);
  if (coords.length !== 24 * n) {
    throw new LinkError(`the link cannot be read: ${n} points need ${24 * n} bytes, found ${coords.length}`);
  }
  const points = fromColumns(unshuffleDoubles(coords));
  const bad = points.findIndex((v) => !Number.isFinite(v));
  if (bad >= 0) throw new LinkError(`the link cannot be read: point ${Math.floor(bad / 3)} has a non-finite coordinate`);

  const objective = OBJECTIVE_IDS.find((id) => id === header.objective);
  if (!objective) throw new LinkError(`the link names an unknown objective ${shown(header.objective)}`);
  // Fields added after the first links were shared may be absent (their old
  // meaning); a field that is there must be what this page writes.
  const field = <T>(name: string, fallback: T, read: (v: unknown) => T | undefined, expected: string): T => {
    if (!Object.hasOwn(header, name)) return fallback;
    const v = read(header[name]);
    if (v === undefined) throw new LinkError(`the link's ${name} is ${shown(header[name])}, expected ${expected}`);
    return v;
  };
  const method = field('method', 'auto' as Method, (v) => METHODS.find((m) => m === v), `one of ${METHODS.join(', ')}`);
  const epsilon = field('epsilon', 0.25, (v) => (typeof v === 'number' && v > 0 && v < 1 ? v : undefined), 'a number between 0 and 1');
  const order = field('order', 1, (v) => (isOrder(v) ? v : undefined), 'an integer from 1 to 8');
  const view = field('view', 'split' as ViewMode, (v) => VIEW_MODES.find((m) => m === v), `one of ${VIEW_MODES.join(', ')}`);
  const positive = (v: unknown) => (typeof v === 'number' && Number.isFinite(v) && v > 0 ? v : undefined);
  const maxEdge = field('maxEdge', null, positive, 'a positive length');
  const exaggeration = field('exaggeration', null, positive, 'a positive factor');
  const source = field('source', null, readSource, `{kind, count, seed} with kind one of ${TERRAIN_KINDS.join(', ')}, count and seed whole numbers`);
  return { points, objective, method, epsilon, order, maxEdge, view, exaggeration, source };
}

function readSource(s: unknown): SharedState['source'] | undefined {
  if (s === null || typeof s !== 'object') return undefined;
  const { kind, count, seed } = s as Record<string, unknown>;
  if (typeof kind !== 'string' || !isTerrainKind(kind)) return undefined;
  const whole = (v: unknown): v is number => typeof v === 'number' && Number.isSafeInteger(v) && v >= 0;
  if (!whole(count) || count > MAX_POINTS || !whole(seed)) return undefined;
  return { kind, count, seed };
}

/** A header value in a message: its JSON, on one line, cut short. */
function shown(v: unknown): string {
  const json = JSON.stringify(v) ?? String(v);
  return json.length > 60 ? `${json.slice(0, 57)}…` : json;
}
