// Fuzzing the link decoder (web/demo/src/share): whatever a hash holds, decodeState
// returns a state every field of which is what the page can use, or throws a
// LinkError with a one-line message; never another error.
import { deflateSync } from 'fflate';
import { OBJECTIVE_IDS } from 'hodt';
import { expect, test } from 'vitest';
import { isOrder, METHODS, VIEW_MODES } from '../../web/demo/src/app/settings.ts';
import { toBase64Url } from '../../web/demo/src/share/base64url.ts';
import { decodeState, encodeState, LinkError, type SharedState } from '../../web/demo/src/share/urlState.ts';
import { seededRandom } from '../../web/demo/src/terrains/rng.ts';

const random = seededRandom(57);
const below = (n: number) => Math.floor(random() * n);
const pick = <T>(xs: readonly T[]): T => xs[below(xs.length)]!;

const valid: SharedState = {
  points: Float64Array.from({ length: 30 }, (_, i) => (i * 7.25) % 13),
  objective: 'min-local-minima',
  method: 'exact',
  epsilon: 0.2,
  order: 2,
  maxEdge: 40,
  view: 'plan',
  source: { kind: 'grid', count: 10, seed: 3 },
  exaggeration: 2.7,
};

/** Values of every JSON type, some right for some field and most wrong. */
const VALUES: unknown[] = [null, true, false, 0, -1, 1, 2.5, 3, 8, 9, 1e308, -0, '', 'auto', 'plan', 'min-local-minima', '2', [], [1, 2], {}, { kind: 'grid' }, { kind: 'grid', count: 5, seed: 1 }, { kind: 'x', count: 1, seed: 1 }];
const FIELDS = ['n', 'objective', 'method', 'epsilon', 'order', 'view', 'source', 'maxEdge', 'exaggeration', 'extra'];

function pack(header: unknown, coords: Uint8Array): string {
  const json = new TextEncoder().encode(JSON.stringify(header) ?? '');
  const out = new Uint8Array(4 + json.length + coords.length);
  new DataView(out.buffer).setUint32(0, json.length, true);
  out.set(json, 4);
  out.set(coords, 4 + json.length);
  return `#v1=${toBase64Url(deflateSync(out))}`;
}

/** A damaged copy of a good link: its text cut, bytes flipped, or its header replaced. */
function mutant(good: string): string {
  switch (below(5)) {
    case 0:
      return good.slice(0, below(good.length));
    case 1: {
      const chars = good.split('');
      for (let i = 0, n = 1 + below(4); i < n; i++) chars[4 + below(chars.length - 4)] = pick('AZaz09-_+/=$%'.split(''));
      return chars.join('');
    }
    case 2: {
      const header: Record<string, unknown> = { n: 10, objective: 'min-local-minima', method: 'auto', epsilon: 0.25, order: 1, view: 'split' };
      for (let i = 0, n = 1 + below(3); i < n; i++) {
        const f = pick(FIELDS);
        if (random() < 0.2) delete header[f];
        else header[f] = pick(VALUES);
      }
      return pack(header, new Uint8Array(240).map(() => below(256)));
    }
    case 3:
      return pack(pick(VALUES), new Uint8Array(below(300)));
    default:
      return `#${pick(['v1', 'v2', 'v0', 'V1', 'v1x', ''])}=${toBase64Url(new Uint8Array(below(64)).map(() => below(256)))}`;
  }
}

function usable(s: SharedState): void {
  expect(s.points.length % 3).toBe(0);
  expect(s.points.length / 3).toBeGreaterThanOrEqual(3);
  expect(s.points.every(Number.isFinite)).toBe(true);
  expect(OBJECTIVE_IDS).toContain(s.objective);
  expect(METHODS).toContain(s.method);
  expect(s.epsilon > 0 && s.epsilon < 1).toBe(true);
  expect(isOrder(s.order)).toBe(true);
  expect(VIEW_MODES).toContain(s.view);
  for (const v of [s.maxEdge, s.exaggeration]) expect(v === null || (Number.isFinite(v) && v > 0)).toBe(true);
  if (s.source) expect(Number.isSafeInteger(s.source.count) && Number.isSafeInteger(s.source.seed)).toBe(true);
}

test('the link decoder answers every damaged link with a state it can use or a LinkError', () => {
  const good = encodeState(valid);
  usable(decodeState(good)!);
  let refused = 0, opened = 0;
  for (let i = 0; i < 3000; i++) {
    const hash = mutant(good);
    let s: SharedState | null;
    try {
      s = decodeState(hash);
    } catch (e) {
      if (!(e instanceof LinkError)) throw new Error(`${hash.slice(0, 80)}: ${String(e)}`);
      expect(e.message).toMatch(/^[^\n]{10,300}$/);
      refused++;
      continue;
    }
    if (s) usable(s), opened++;
  }
  // Both outcomes are exercised.
  expect(refused).toBeGreaterThan(1000);
  expect(opened).toBeGreaterThan(10);
});
