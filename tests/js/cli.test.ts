// The CLI contract (README "CLI"), run as users run it: `node dist/cli.js`, and the
// native build of the same core, which must print the same JSON.
import { spawnSync } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';

const root = new URL('../../', import.meta.url).pathname;
const fixture = (name: string) => `${root}tests/fixtures/${name}`;
const goodFixtures = readdirSync(fixture('')).filter((f) => !f.startsWith('bad-') && f !== 'make.mjs');

function hodt(args: string[], input?: string) {
  const r = spawnSync('node', [`${root}dist/cli.js`, ...args], { encoding: 'utf8', input });
  return { code: r.status, out: r.stdout, err: r.stderr };
}
function native(args: string[]) {
  const r = spawnSync(`${root}build/native/hodt`, args, { encoding: 'utf8' });
  return { code: r.status, out: r.stdout, err: r.stderr };
}
// The JSON of a result without its timings, which differ run to run.
const withoutTime = (text: string) => {
  const j = JSON.parse(text);
  delete j.timeMs;
  delete j.times;
  return j;
};

const IDS = [
  'max-convex-vertices', 'minmax-edge-area-ratio', 'minmax-edge-normal-angle', 'minmax-edge-enclosing-circle',
  'minmax-vertex-area-ratio', 'minmax-vertex-normal-angle', 'min-local-minima', 'min-local-extrema',
  'min-total-edge-length', 'minmax-triangle-area', 'max-convex-edges', 'min-mixed-vertices', 'minmax-degree',
];

describe('hodt stats', () => {
  it('prints the documented keys and all 13 Delaunay values', () => {
    const r = hodt(['stats', fixture('uniform-50.csv')]);
    expect(r.code).toBe(0);
    const j = JSON.parse(r.out);
    expect(Object.keys(j)).toEqual(['points', 'triangles', 'edges', 'flippable', 'hullVertices', 'delaunay', 'drainage']);
    expect(Object.keys(j.delaunay)).toEqual(IDS);
    // Every local minimum is a pit; the lowest point drains nowhere.
    expect(j.drainage.pits).toBeGreaterThanOrEqual(j.delaunay['min-local-minima']);
    expect(j.drainage.pits + j.drainage.outlets).toBeGreaterThanOrEqual(1);
    expect(j.points).toBe(50);
    // Euler's formula for a triangulated convex polygon.
    expect(j.triangles).toBe(2 * j.points - j.hullVertices - 2);
    expect(j.edges).toBe(3 * j.points - j.hullVertices - 3);
  });

  it.each(goodFixtures)('wasm and native print the same for %s', (name) => {
    expect(hodt(['stats', fixture(name)]).out).toBe(native(['stats', fixture(name)]).out);
  });

  it('a semicolon file with decimal commas reads as its decimal-point twin', () => {
    const twin = '0 0 1.5\n10.25 0 2.25\n10.25 9.5 0.75\n0 9.5 3\n4.5 4.75 8.125\n';
    const r = hodt(['stats', fixture('semicolon-decimal-comma.csv')]);
    expect(r.code).toBe(0);
    expect(r.err).toBe('');
    expect(r.out).toBe(hodt(['stats', '-'], twin).out);
  });

  it('--crs takes EPSG codes in their usual spellings into the output', () => {
    for (const spelling of ['EPSG:32633', 'epsg:32633', 'urn:ogc:def:crs:EPSG::32633', 'http://www.opengis.net/def/crs/EPSG/0/32633', '32633']) {
      const r = hodt(['stats', fixture('uniform-12.csv'), '--crs', spelling]);
      expect(r.code).toBe(0);
      expect(JSON.parse(r.out).crs).toBe('EPSG:32633');
    }
    expect(JSON.parse(hodt(['stats', fixture('uniform-12.csv'), '--crs', '+proj=utm +zone=33 +datum=WGS84']).out).crs).toBe('+proj=utm +zone=33 +datum=WGS84');
  });

  it('reads standard input with -', () => {
    const r = hodt(['stats', '-'], '0 0 0\n1 0 1\n0 1 2\n1 1 0\n');
    expect(r.code).toBe(0);
    expect(JSON.parse(r.out).points).toBe(4);
  });
});

describe('hodt solve', () => {
  it('prints the documented result, triangles on request', () => {
    const r = hodt(['solve', fixture('uniform-12.csv'), '--objective', 'max-convex-edges', '--method', 'brute-force', '--triangles']);
    expect(r.code).toBe(0);
    const j = JSON.parse(r.out);
    expect(Object.keys(j)).toEqual(['objective', 'sense', 'method', 'value', 'delaunayValue', 'optimal', 'bound', 'flipped', 'timeMs', 'times', 'drainage', 'triangles']);
    expect(j).toMatchObject({ objective: 'max-convex-edges', sense: 'max', method: 'brute-force', optimal: true, bound: null });
    expect(j.value).toBeGreaterThanOrEqual(j.delaunayValue);
    expect(j.triangles).toHaveLength(JSON.parse(hodt(['stats', fixture('uniform-12.csv')]).out).triangles);
    for (const t of j.triangles) expect(t).toHaveLength(3);
  });

  it.each(IDS)('wasm and native agree on brute force for %s', (id) => {
    const args = ['solve', fixture('uniform-12.csv'), '--objective', id, '--method', 'brute-force', '--triangles'];
    const w = hodt(args), n = native(args);
    expect(w.code).toBe(0);
    expect(withoutTime(w.out)).toEqual(withoutTime(n.out));
  });
});

describe('bad input: exit 2 and one line naming what is wrong', () => {
  const cases: [string, string[], RegExp][] = [
    ['NaN', ['stats', fixture('bad-nan.csv')], /bad-nan\.csv: line 4: z is 'nan'/],
    ['infinite', ['stats', fixture('bad-infinite.csv')], /bad-infinite\.csv: line 3: x is 'inf'/],
    ['duplicate', ['stats', fixture('bad-duplicate.csv')], /point 1 \(line 2\) and point 3 \(line 4\) have the same \(x, y\) = \(1, 0\)/],
    ['too few', ['stats', fixture('bad-too-few.csv')], /need at least 3 distinct points, got 2/],
    ['collinear', ['stats', fixture('bad-collinear.csv')], /all 4 points are collinear/],
    ['field count', ['stats', fixture('bad-field-count.csv')], /line 2: expected 3 numbers x y z, got 2 fields/],
    ['not a number', ['stats', fixture('bad-not-a-number.csv')], /line 2: y is 'zero', not a number/],
    ['bad JSON', ['stats', fixture('bad-json.json')], /bad-json\.json: line 1: point 2: expected \[x, y, z\]/],
    ['bad grid', ['stats', fixture('bad-grid-row.asc')], /line 7: expected ncols = 3 values, got 2/],
    ['empty', ['stats', fixture('bad-empty.csv')], /the file is empty/],
    ['missing file', ['stats', fixture('no-such-file.csv')], /no-such-file\.csv: no such file/],
    ['unknown objective', ['solve', fixture('uniform-12.csv'), '--objective', 'max-fun'], /unknown objective 'max-fun'; valid objectives: max-convex-vertices, .*minmax-degree/],
    ['unknown method', ['solve', fixture('uniform-12.csv'), '--objective', 'minmax-degree', '--method', 'magic'], /unknown method 'magic'; valid methods: brute-force, exact, approx, auto/],
    ['missing objective', ['solve', fixture('uniform-12.csv')], /solve needs --objective ID; valid objectives:/],
    ['unknown option', ['stats', fixture('uniform-12.csv'), '--frobnicate'], /unknown option '--frobnicate'/],
    ['bad epsilon', ['solve', fixture('uniform-12.csv'), '--objective', 'minmax-degree', '--epsilon', 'x'], /--epsilon expects a number, got 'x'/],
    ['epsilon out of range', ['solve', fixture('uniform-12.csv'), '--objective', 'minmax-degree', '--epsilon', '2'], /epsilon is 2, expected a number in \(0, 1\)/],
    ['mixed delimiters', ['stats', fixture('bad-mixed-delimiters.csv')], /line 2: expected 3 numbers x y z separated by ';' as on line 1, got 1 field '4,5,6'$/m],
    ['mixed decimal marks', ['stats', fixture('bad-mixed-decimal-marks.csv')], /line 2: x is '2\.5' with a decimal point, but line 1 has decimal commas: one decimal mark per file$/m],
    ['an id column and no header', ['stats', fixture('bad-id-column-no-header.csv')], /line 1: 4 columns \(','\) and no header naming x, y and z; add a first line naming the columns, such as 'id,x,y,z'/],
    ['a JSON key holding newlines', ['stats', fixture('bad-json-key-newlines.json')], /line 1: point 0: unexpected key 'y\\n\\n\\n', expected x, y, z$/m],
    ['control characters', ['stats', fixture('bad-control-characters.csv')], /line 2: y is '\\x1b\[31m\\x07\\x00', not a number$/m],
    ['--crs that is no CRS', ['stats', fixture('uniform-12.csv'), '--crs', 'foo'], /--crs expects an EPSG code \(EPSG:32633\), a WKT definition or a PROJ string \(\+proj=\.\.\.\), got 'foo'$/m],
    ['--crs with a line break', ['stats', fixture('uniform-12.csv'), '--crs', 'EPSG:4326\nx'], /got 'EPSG:4326\\nx'$/m],
  ];
  it.each(cases)('%s', (_name, args, message) => {
    const r = hodt(args);
    expect(r.code).toBe(2);
    expect(r.out).toBe('');
    expect(r.err).toMatch(message);
    expect(r.err.trim().split('\n')).toHaveLength(1);
    expect(r.err).not.toMatch(/at .*\.js|RuntimeError|Aborted/);
  });

  it('a refused request (brute force on too many quads) exits 3 with the reason', () => {
    const r = hodt(['solve', fixture('uniform-300.csv'), '--objective', 'min-local-minima', '--method', 'brute-force']);
    expect(r.code).toBe(3);
    expect(r.err).toMatch(/refuses m = \d+ flippable quads \(at most 24\)/);
  });
});

describe('exact methods from the CLI', () => {
  it.each(IDS)('%s: exact equals brute force, native equals wasm', (id) => {
    const args = ['solve', fixture('uniform-12.csv'), '--objective', id];
    const exact = JSON.parse(hodt([...args, '--method', 'exact']).out);
    const brute = JSON.parse(hodt([...args, '--method', 'brute-force']).out);
    expect(exact.optimal).toBe(true);
    expect(exact.value).toBeCloseTo(brute.value, 12);
    expect(withoutTime(hodt([...args, '--method', 'exact', '--triangles']).out)).toEqual(
      withoutTime(native([...args, '--method', 'exact', '--triangles']).out),
    );
  });

  it('min-max objectives report the critical pair and, with --trace, the search', () => {
    const r = hodt(['solve', fixture('dem-hills-400.txt'), '--objective', 'minmax-edge-normal-angle', '--method', 'exact', '--trace']);
    expect(r.code).toBe(0);
    const j = JSON.parse(r.out);
    expect(j.critical.value).toBe(j.value);
    expect(j.critical.first).toHaveLength(3);
    expect(j.trace.length).toBeGreaterThan(0);
    for (const step of j.trace) {
      expect(Object.keys(step)).toEqual(['threshold', 'satisfiable', 'clauses']);
      expect(step.satisfiable).toBe(step.threshold >= j.value);
    }
    expect(j.value).toBeLessThanOrEqual(j.delaunayValue);
  });

  it('exact runs on a few hundred points for every objective, same as native', () => {
    for (const id of IDS) {
      const args = ['solve', fixture('dem-hills-400.txt'), '--objective', id, '--method', 'exact'];
      const w = hodt(args);
      expect(w.code).toBe(0);
      expect(withoutTime(w.out)).toEqual(withoutTime(native(args).out));
    }
  });
});

describe('higher order: hodt stats --order K', () => {
  it('adds useful edge and triangle counts; order 1 is Delaunay plus the flipped diagonals', () => {
    const plain = JSON.parse(hodt(['stats', fixture('uniform-300.csv')]).out);
    expect(plain.usefulEdges).toBeUndefined();
    const one = JSON.parse(hodt(['stats', fixture('uniform-300.csv'), '--order', '1']).out);
    expect(one.usefulEdges).toBe(one.edges + one.flippable);
    let last = one;
    for (const k of [2, 3, 4, 8]) {
      const j = JSON.parse(hodt(['stats', fixture('dem-hills-400.txt'), '--order', String(k)]).out);
      expect(j.order).toBe(k);
      expect(j.usefulEdges).toBeGreaterThanOrEqual(k === 2 ? 0 : last.usefulEdges);
      expect(j.usefulTriangles).toBeGreaterThan(0);
      expect(withoutTime(hodt(['stats', fixture('dem-hills-400.txt'), '--order', String(k)]).out)).toEqual(
        withoutTime(native(['stats', fixture('dem-hills-400.txt'), '--order', String(k)]).out),
      );
      last = j;
    }
  });
  it('rejects a bad order', () => {
    const r = hodt(['stats', fixture('uniform-12.csv'), '--order', '0']);
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/--order expects an integer from 1 to 16/);
  });
});

describe('higher order: hodt solve --order K', () => {
  it('exact by enumeration on small inputs, k-OD and no worse than first order', () => {
    let previous = Infinity;
    for (const k of [1, 2, 3]) {
      const args = ['solve', fixture('uniform-12.csv'), '--objective', 'min-local-minima', '--order', String(k), '--triangles'];
      const j = JSON.parse(hodt(args).out);
      expect(j.optimal).toBe(true);
      expect(j.value).toBeLessThanOrEqual(previous);
      previous = j.value;
      expect(withoutTime(hodt(args).out)).toEqual(withoutTime(native(args).out));
    }
  });
  it('exact over the regions on larger inputs; approx is a local search with a bound', () => {
    const args = ['solve', fixture('dem-hills-400.txt'), '--objective', 'min-local-minima', '--order', '4'];
    const exact = JSON.parse(hodt(args).out);
    // Exact over the regions, or (a region over its budget) the heuristic, here proven optimal by its bound.
    expect(exact).toMatchObject({ order: 4, optimal: true, bound: null });
    expect(['exact', 'heuristic']).toContain(exact.method);
    const exact3 = JSON.parse(hodt(['solve', fixture('dem-hills-400.txt'), '--objective', 'min-local-minima', '--order', '3']).out);
    expect(exact3).toMatchObject({ method: 'exact', order: 3, optimal: true, bound: null });
    expect(exact.value).toBeLessThanOrEqual(exact.delaunayValue);
    const approx = JSON.parse(hodt([...args, '--method', 'approx']).out);
    expect(approx.method).toBe(approx.optimal ? 'exact' : 'heuristic');
    expect(approx.value).toBeGreaterThanOrEqual(exact.value);
    if (!approx.optimal) expect(approx.bound).toBeLessThanOrEqual(exact.value);
  });
});
