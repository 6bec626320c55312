import { deflateSync } from 'fflate';
import { OBJECTIVE_IDS, type Method, type ObjectiveId } from 'hodt';
import { isOrder, METHODS, VIEW_MODES, type ViewMode } from '../app/settings.ts';
import { isTerrainKind, type TerrainKind } from '../terrains/kinds.ts';
import { fromBase64Url, toBase64Url } from './base64url.ts';
import { boundedInflate } from './boundedInflate.ts';
import { fromColumns, shuffleDoubles, toColumns, unshuffleDoubles } from './byteShuffle.ts';

/**
 * The whole page state in the URL hash: `#v1=<base64url>`, the raw deflate of
 *   u32 (little-endian) length L of a JSON header,
 *   L bytes of UTF-8 JSON {n, objective, method, epsilon, order, view, source?,
 *     maxEdge?} (order and maxEdge were added later: links without them mean
 *     order 1 and no domain),
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
    }),
  );
  const coords = shuffleDoubles(toColumns(s.points));
  const raw = new Uint8Array(4 + header.length + coords.length);
  new DataView(raw.buffer).setUint32(0, header.length, true);
  raw.set(header, 4);
  raw.set(coords, 4 + header.length);
  return `#${HASH_VERSION}=${toBase64Url(deflateSync(raw, { level: 9 }))}`;
}

/** Null for an empty hash; throws LinkError with a message for a user. */
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
  let header: Record<string, unknown>;
  try {
    header = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(raw.subarray(4, 4 + length)));
  } catch {
    throw new LinkError('the link cannot be read: its header is not valid JSON');
  }
  const n = header.n;
  if (typeof n !== 'number' || !Number.isInteger(n) || n < 3 || n > MAX_POINTS) {
    throw new LinkError(`the link cannot be read: bad point count ${JSON.stringify(n)}`);
  }
  const coords = raw.subarray(4 + length);
  if (coords.length !== 24 * n) {
    throw new LinkError(`the link cannot be read: ${n} points need ${24 * n} bytes, found ${coords.length}`);
  }
  const points = fromColumns(unshuffleDoubles(coords));
  const bad = points.findIndex((v) => !Number.isFinite(v));
  if (bad >= 0) throw new LinkError(`the link cannot be read: point ${Math.floor(bad / 3)} has a non-finite coordinate`);

  const objective = OBJECTIVE_IDS.find((id) => id === header.objective);
  if (!objective) throw new LinkError(`the link names an unknown objective ${JSON.stringify(header.objective)}`);
  const method = METHODS.find((m) => m === header.method) ?? 'auto';
  const epsilon = typeof header.epsilon === 'number' && header.epsilon > 0 && header.epsilon < 1 ? header.epsilon : 0.25;
  const order = isOrder(header.order) ? header.order : 1;
  const view = VIEW_MODES.find((v) => v === header.view) ?? 'split';
  const maxEdge = typeof header.maxEdge === 'number' && Number.isFinite(header.maxEdge) && header.maxEdge > 0 ? header.maxEdge : null;
  return { points, objective, method, epsilon, order, maxEdge, view, source: readSource(header.source) };
}

function readSource(s: unknown): SharedState['source'] {
  if (s === null || typeof s !== 'object') return null;
  const { kind, count, seed } = s as Record<string, unknown>;
  if (typeof kind !== 'string' || !isTerrainKind(kind)) return null;
  if (typeof count !== 'number' || typeof seed !== 'number') return null;
  return { kind, count, seed };
}
