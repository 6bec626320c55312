// The link format (web/demo/src/share): exact doubles, versioned, and every bad
// link refused with a message instead of a crash.
import { deflateSync } from 'fflate';
import { describe, expect, test } from 'vitest';
import { fromBase64Url, toBase64Url } from '../../web/demo/src/share/base64url.ts';
import { shuffleDoubles, toColumns } from '../../web/demo/src/share/byteShuffle.ts';
import { decodeState, encodeState, LinkError, MAX_HASH_CHARS, type SharedState } from '../../web/demo/src/share/urlState.ts';

const state = (points: Float64Array): SharedState => ({
  points,
  objective: 'minmax-degree',
  method: 'approx',
  epsilon: 0.1,
  order: 3,
  maxEdge: 12.5,
  view: 'plan',
  source: { kind: 'fractal', count: 300, seed: 42 },
  exaggeration: 2.7,
});

describe('link state', () => {
  test('round-trips the exact bits of every coordinate and the settings', () => {
    const tricky = [-0, 0, 1e-310, -1e-310, Number.MIN_VALUE, Number.MAX_VALUE, -Number.MAX_VALUE, 0.1, 1 / 3, Math.PI, 6378137.000000001, -4.5e15, 2 ** 53 + 2];
    const points = new Float64Array(3 * 400);
    for (let i = 0; i < points.length; i++) points[i] = i < tricky.length ? tricky[i]! : (Math.random() - 0.5) * 10 ** (i % 20);
    const hash = encodeState(state(points));
    expect(hash).toMatch(/^#v1=[A-Za-z0-9_-]+$/);
    const back = decodeState(hash)!;
    expect(new Uint8Array(back.points.buffer)).toEqual(new Uint8Array(points.buffer));
    expect(Object.is(back.points[0], -0)).toBe(true);
    expect({ ...back, points: null }).toEqual({ ...state(points), points: null });
  });

  test('compresses typical terrains well below the raw size', () => {
    const n = 1500;
    const points = new Float64Array(3 * n);
    for (let i = 0; i < n; i++) points.set([Math.random() * 860, Math.random() * 600, 90 + Math.random() * 100], 3 * i);
    const hash = encodeState(state(points));
    expect(hash.length).toBeLessThan(((24 * n) / 3) * 4); // < base64 of the raw doubles
  });

  test('refuses bad links with a message', () => {
    const bad = (hash: string, message: RegExp) => {
      expect(() => decodeState(hash)).toThrow(LinkError);
      expect(() => decodeState(hash)).toThrow(message);
    };
    expect(decodeState('')).toBeNull();
    expect(decodeState('#')).toBeNull();
    bad('#v2=AAAA', /format v2/);
    bad('#x=1', /no state/);
    bad('#v1=a+b/', /base64url/);
    bad('#v1=A', /length/);
    bad(`#v1=${'A'.repeat(MAX_HASH_CHARS)}`, /too long/);
    bad('#v1=AAAAAAAA', /damaged|truncated/);
    // A deflate bomb: a small link that would inflate to gigabytes.
    bad(`#v1=${toBase64Url(deflateSync(new Uint8Array(40_000_000)))}`, /more than/);
    const raw = (header: object, coords: Float64Array) => {
      const json = new TextEncoder().encode(JSON.stringify(header));
      const out = new Uint8Array(4 + json.length + coords.byteLength);
      new DataView(out.buffer).setUint32(0, json.length, true);
      out.set(json, 4);
      out.set(shuffleDoubles(toColumns(coords)), 4 + json.length);
      return `#v1=${toBase64Url(deflateSync(out))}`;
    };
    const ok = { n: 3, objective: 'min-local-minima', method: 'auto', epsilon: 0.25, view: 'split' };
    expect(decodeState(raw(ok, new Float64Array(9)))!.points).toHaveLength(9);
    // Links made before the order control keep working: they mean order 1.
    expect(decodeState(raw(ok, new Float64Array(9)))!.order).toBe(1);
    expect(decodeState(raw({ ...ok, order: 5 }, new Float64Array(9)))!.order).toBe(5);
    // A field that is there must be what the page writes.
    for (const order of [0, 9, 2.5, '2', null]) bad(raw({ ...ok, order }, new Float64Array(9)), /order is .*, expected an integer from 1 to 8/);
    // ... and no domain; a link's domain is a positive length.
    expect(decodeState(raw(ok, new Float64Array(9)))!.maxEdge).toBeNull();
    expect(decodeState(raw({ ...ok, maxEdge: 3.25 }, new Float64Array(9)))!.maxEdge).toBe(3.25);
    for (const maxEdge of [0, -1, '2', null, 1e400]) bad(raw({ ...ok, maxEdge }, new Float64Array(9)), /maxEdge is .*, expected a positive length/);
    // ... and automatic heights.
    expect(decodeState(raw(ok, new Float64Array(9)))!.exaggeration).toBeNull();
    expect(decodeState(raw({ ...ok, exaggeration: 2.7 }, new Float64Array(9)))!.exaggeration).toBe(2.7);
    // Headers that are not objects, and fields of the wrong type.
    for (const header of [null, [], 3, 'v1', true]) bad(raw(header as object, new Float64Array(9)), /its header is .*, expected an object/);
    bad(raw({ ...ok, method: 7 }, new Float64Array(9)), /method is 7, expected one of auto/);
    bad(raw({ ...ok, epsilon: '0.25' }, new Float64Array(9)), /epsilon is "0.25"/);
    bad(raw({ ...ok, view: null }, new Float64Array(9)), /view is null/);
    bad(raw({ ...ok, source: { kind: 'grid', count: -1, seed: 2 } }, new Float64Array(9)), /source is /);
    bad(raw({ ...ok, objective: 'x'.repeat(5000) }, new Float64Array(9)), /unknown objective "x{50,}…$/);
    bad(raw({ ...ok, n: 4 }, new Float64Array(9)), /4 points need 96 bytes/);
    bad(raw({ ...ok, n: 2 }, new Float64Array(6)), /bad point count/);
    bad(raw({ ...ok, objective: 'nope' }, new Float64Array(9)), /unknown objective/);
    bad(raw(ok, new Float64Array([0, 0, 0, 1, NaN, 0, 0, 1, 0])), /point 1 has a non-finite/);
  });

  test('base64url round-trips any bytes', () => {
    for (const length of [0, 1, 2, 3, 4, 5, 100, 70_000]) {
      const bytes = Uint8Array.from({ length }, (_, i) => (i * 97 + 13) & 255);
      expect(fromBase64Url(toBase64Url(bytes))).toEqual(bytes);
    }
  });
});
