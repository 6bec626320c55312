// Options and arguments are checked the same way at every order and through every
// front end: the core's check_options for the values (JS and both CLIs print its
// message), typed InputErrors naming the argument for what embind cannot carry.
import { spawnSync } from 'node:child_process';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, InputError, LimitError, loadHodt, type Terrain } from '../../web/src/index.js';
import { randomPoints } from './randomPoints.js';

const root = new URL('../../', import.meta.url).pathname;
const fixture = (name: string) => `${root}tests/fixtures/${name}`;

let hodt: Hodt;
let small: Terrain;

beforeAll(async () => {
  hodt = await loadHodt();
  small = hodt.terrain(randomPoints(12, 3));
});
afterAll(() => small.dispose());

describe('solve options, at every order', () => {
  const bad: [number, string][] = [
    [Number.NaN, 'NaN'],
    [2, '2'],
    [-1, '-1'],
    [0, '0'],
    [Number.POSITIVE_INFINITY, 'Infinity'],
    [1e309, 'Infinity'],
  ];
  it.each([1, 2, 5])('epsilon outside (0, 1) is an InputError at order %i', (order) => {
    for (const [epsilon, shown] of bad) {
      expect(() => small.solve('min-local-minima', { order, epsilon })).toThrow(
        new InputError(`epsilon is ${shown}, expected a number in (0, 1)`),
      );
    }
  });
  it('every method at order k: brute force and exact enumerate or refuse, approx is the heuristic', () => {
    const best = small.solve('max-convex-edges', { order: 2 }).value;
    expect(small.solve('max-convex-edges', { order: 2, method: 'brute-force' })).toMatchObject({ order: 2, method: 'brute-force', optimal: true, value: best });
    expect(small.solve('max-convex-edges', { order: 2, method: 'exact' })).toMatchObject({ order: 2, method: 'exact', optimal: true, value: best });
    const approx = small.solve('max-convex-edges', { order: 2, method: 'approx' });
    expect(approx.method).toBe(approx.optimal ? 'exact' : 'heuristic');
    using large = hodt.terrain(randomPoints(200, 3));
    expect(() => large.solve('min-local-minima', { order: 2, method: 'brute-force' })).toThrow(LimitError);
    expect(() => large.solve('min-local-minima', { order: 2, method: 'brute-force' })).toThrow(
      'brute force at order 2 enumerates every k-OD triangulation and refuses 200 points (at most 30)',
    );
  });
  it('non-numbers are named, whatever the order', () => {
    expect(() => small.solve('min-local-minima', { order: 2, epsilon: '0.1' as never })).toThrow(
      new InputError("epsilon is '0.1', expected a number"),
    );
    expect(() => small.solve('min-local-minima', { order: 2n as never })).toThrow(new InputError('order is 2n, expected a number'));
    expect(() => small.usefulEdges('2' as never)).toThrow(new InputError("order is '2', expected a number"));
  });
});

describe('terrain arguments', () => {
  it("dedupe is 'error' or 'first'", () => {
    const xyz = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 5];
    for (const dedupe of ['last', 'First', true, 1])
      expect(() => hodt.terrain(xyz, { dedupe: dedupe as never })).toThrow(
        new InputError(`dedupe is ${typeof dedupe === 'string' ? `'${dedupe}'` : String(dedupe)}, expected 'error' or 'first'`),
      );
    expect(() => hodt.terrain(xyz, { dedupe: 'error' })).toThrow(InputError);  // the duplicate itself
    hodt.terrain(xyz, { dedupe: 'first' }).dispose();
    hodt.terrain(xyz.slice(0, 9)).dispose();  // default 'error', no duplicate
  });
  it('edits name a coordinate or index that is not a number', () => {
    using t = hodt.terrain(randomPoints(20, 4));
    expect(() => t.addPoint(1n as never, 0.5, 0)).toThrow(new InputError('point 20: x is 1n, expected a finite number'));
    expect(() => t.addPoint(0.5, '0.5' as never, 0)).toThrow(new InputError("point 20: y is '0.5', expected a finite number"));
    expect(() => t.addPoint(0.5, 0.5, undefined as never)).toThrow(new InputError('point 20: z is undefined, expected a finite number'));
    expect(() => t.movePoint(3, 0.5, 0.5, 2n as never)).toThrow(new InputError('point 3: z is 2n, expected a finite number'));
    expect(() => t.movePoint('3' as never, 0.5, 0.5, 0)).toThrow(new InputError("point index is '3', expected an integer"));
    expect(() => t.removePoint(1n as never)).toThrow(new InputError('point index is 1n, expected an integer'));
    expect(t.numInputPoints).toBe(20);  // nothing changed
  });
  it('a point dropped as a duplicate can be removed; later indices shift down', () => {
    // Points 1 and 3 share (x, y): 'first' keeps point 1.
    const xyz = [0, 0, 0, 1, 0, 1, 0, 1, 2, 1, 0, 3, 1, 1, 4];
    using t = hodt.terrain(xyz, { dedupe: 'first' });
    expect(t.numInputPoints).toBe(5);
    expect(Array.from(t.vertexIndex)).toEqual([0, 1, 2, 4]);
    t.removePoint(3);
    expect(t.numInputPoints).toBe(4);
    expect(Array.from(t.vertexIndex)).toEqual([0, 1, 2, 3]);
    expect(Array.from(t.points)).toEqual([0, 0, 0, 1, 0, 1, 0, 1, 2, 1, 1, 4]);
    using fresh = hodt.terrain(t.points);
    const sorted = (a: Uint32Array) => Array.from(a).sort((p, q) => p - q);
    expect(sorted(t.delaunay().triangles)).toEqual(sorted(fresh.delaunay().triangles));
    expect(() => t.removePoint(4)).toThrow(new InputError('point 4 is out of range (4 points)'));
  });
});

describe('CLI: the same one-line message from the native and the wasm binary', () => {
  const run = (command: string[], args: string[]) => {
    const r = spawnSync(command[0]!, [...command.slice(1), ...args], { encoding: 'utf8' });
    return { code: r.status, out: r.stdout, err: r.stderr };
  };
  const wasm = (args: string[]) => run(['node', `${root}dist/cli.js`], args);
  const native = (args: string[]) => run([`${root}build/native/hodt`], args);
  const solve = ['solve', fixture('uniform-12.csv'), '--objective', 'max-convex-edges'];
  const cases: [string[], string][] = [
    [['--epsilon', '2'], 'hodt: epsilon is 2, expected a number in (0, 1)\n'],
    [['--epsilon', '-1'], 'hodt: epsilon is -1, expected a number in (0, 1)\n'],
    [['--epsilon', '1e309'], 'hodt: epsilon is Infinity, expected a number in (0, 1)\n'],
    [['--epsilon', 'NaN'], 'hodt: epsilon is NaN, expected a number in (0, 1)\n'],
    [['--epsilon', 'abc'], "hodt: --epsilon expects a number, got 'abc'\n"],
    [['--order', '17'], "hodt: --order expects an integer from 1 to 16, got '17'\n"],
  ];
  it.each(cases)('%j', (extra, message) => {
    for (const order of extra.includes('--order') ? [[]] : [[], ['--order', '2'], ['--order', '3']]) {
      const args = [...solve, ...extra, ...order];
      const w = wasm(args), n = native(args);
      expect(w).toEqual({ code: 2, out: '', err: message });
      expect(n).toEqual(w);
    }
  });
  it('brute force at order 2 enumerates, and refuses beyond its limit', () => {
    const args = [...solve, '--method', 'brute-force', '--order', '2'];
    const w = wasm(args), n = native(args);
    expect(w.code).toBe(0);
    expect(JSON.parse(w.out)).toMatchObject({ method: 'brute-force', optimal: true });
    const drop = (text: string) => ({ ...JSON.parse(text), timeMs: 0, times: null });
    expect(drop(n.out)).toEqual(drop(w.out));
    const large = ['solve', fixture('uniform-300.csv'), '--objective', 'min-local-minima', '--method', 'brute-force', '--order', '2'];
    const w300 = wasm(large);
    expect(w300).toMatchObject({ code: 3, out: '' });
    expect(w300.err).toMatch(/^hodt: brute force at order 2 enumerates every k-OD triangulation and refuses 300 points \(at most 30\)/);
    expect(w300.err.split('\n')).toHaveLength(2);  // one line
    expect(native(large)).toEqual(w300);
  });
});
