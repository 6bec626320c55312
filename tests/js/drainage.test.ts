// terrain.drainage() and `--drainage` against an implementation of the definition
// (DEFINITIONS.md, "Drainage") written here from scratch: neighbours read off the
// triangles, slopes compared in exact rational arithmetic (BigInt), each path
// walked down to its end. Random, DEM-like and flat integer terrains (ties in
// height and slope everywhere), Delaunay and solved at orders 1 to 3, with and
// without a domain; then the CLI, native and npm, and bad triangles.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { getIssues } from '@placemarkio/check-geojson';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type Drainage, type Hodt, InputError, loadHodt, type Terrain } from '../../web/src/index.js';
import { randomPoints } from './randomPoints.js';

let hodt: Hodt;
let dir: string;
beforeAll(async () => {
  hodt = await loadHodt();
  dir = mkdtempSync(join(tmpdir(), 'hodt-drainage-'));
});
afterAll(() => rmSync(dir, { recursive: true, force: true }));

// A double as m * 2^e exactly (m an integer), from its bits.
function exactParts(x: number): { m: bigint; e: number } {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const bits = view.getBigUint64(0);
  const sign = bits >> 63n ? -1n : 1n;
  const biased = Number((bits >> 52n) & 0x7ffn);
  const fraction = bits & ((1n << 52n) - 1n);
  return biased === 0 ? { m: sign * fraction, e: -1074 } : { m: sign * (fraction | (1n << 52n)), e: biased - 1075 };
}
// All coordinates as integers in one scale 2^-low (low: the smallest exponent): the
// differences, squares and products below are then exact integers.
function exactCoordinates(xyz: ArrayLike<number>, extra: number[] = []): { at: (i: number) => bigint; scaled: (x: number) => bigint } {
  const low = Math.min(...Array.from(xyz, (x) => exactParts(x).e), ...extra.map((x) => exactParts(x).e));
  const scaled = (x: number) => {
    const { m, e } = exactParts(x);
    return m << BigInt(e - low);
  };
  const ints = Array.from(xyz, scaled);
  return { at: (i) => ints[i]!, scaled };
}

interface ReferenceDrainage {
  downstream: number[];
  basin: number[];
  accumulation: number[];
  pits: number[];
  outlets: number[];
  localMinima: number;
}

// The definition, directly, on triangles in point indices; `vertices`: the points
// that are vertices (not dropped duplicates).
function referenceDrainage(xyz: ArrayLike<number>, triangles: ArrayLike<number>, maxEdge: number | null): ReferenceDrainage {
  const n = xyz.length / 3;
  const { at, scaled } = exactCoordinates(xyz, maxEdge === null ? [] : [maxEdge]);
  const directed = new Set<string>();
  for (let t = 0; t < triangles.length; t += 3)
    for (let k = 0; k < 3; k++) directed.add(`${triangles[t + k]} ${triangles[t + ((k + 1) % 3)]}`);
  const neighbours = Array.from({ length: n }, () => new Set<number>());
  const boundary = new Array<boolean>(n).fill(false);
  const vertex = new Array<boolean>(n).fill(false);
  for (const key of directed) {
    const [u, v] = key.split(' ').map(Number) as [number, number];
    neighbours[u]!.add(v), neighbours[v]!.add(u);
    vertex[u] = vertex[v] = true;
    if (!directed.has(`${v} ${u}`)) boundary[u] = boundary[v] = true; // a hull edge
  }
  const dx = (u: number, v: number) => at(3 * u) - at(3 * v), dy = (u: number, v: number) => at(3 * u + 1) - at(3 * v + 1);
  const length2 = (u: number, v: number) => dx(u, v) ** 2n + dy(u, v) ** 2n;
  if (maxEdge !== null) {
    const limit = scaled(maxEdge) ** 2n;
    for (let t = 0; t < triangles.length; t += 3) {
      const c = [triangles[t]!, triangles[t + 1]!, triangles[t + 2]!];
      if (c.some((u, k) => length2(u, c[(k + 1) % 3]!) > limit)) for (const u of c) boundary[u] = true;
    }
  }
  const z = (v: number) => xyz[3 * v + 2]!;
  // slope(v -> a) > slope(v -> b), both descents: drop_a^2 |vb|^2 > drop_b^2 |va|^2.
  const steeper = (v: number, a: number, b: number) => {
    const da = at(3 * v + 2) - at(3 * a + 2), db = at(3 * v + 2) - at(3 * b + 2);
    return da * da * length2(v, b) > db * db * length2(v, a);
  };
  const downstream = new Array<number>(n).fill(-1);
  const pits: number[] = [], outlets: number[] = [];
  let localMinima = 0;
  for (let v = 0; v < n; v++) {
    if (!vertex[v]) continue;
    for (const u of [...neighbours[v]!].sort((a, b) => a - b)) {
      if (z(u) < z(v) && (downstream[v] === -1 || steeper(v, u, downstream[v]!))) downstream[v] = u; // ties keep the smaller
    }
    if (downstream[v] === -1) (boundary[v] ? outlets : pits).push(v);
    if (!boundary[v] && [...neighbours[v]!].every((u) => z(u) > z(v))) localMinima++;
  }
  const basin = new Array<number>(n).fill(-1), accumulation = new Array<number>(n).fill(0);
  for (let v = 0; v < n; v++) {
    if (!vertex[v]) continue;
    let w = v;
    for (let steps = 0; ; steps++) {
      expect(steps).toBeLessThanOrEqual(n); // no cycle
      accumulation[w]!++;
      if (downstream[w] === -1) break;
      w = downstream[w]!;
    }
    basin[v] = w;
  }
  return { downstream, basin, accumulation, pits, outlets, localMinima };
}

// The library's network against the reference, and the invariants.
function checkDrainage(terrain: Terrain, triangles: Uint32Array | undefined, localMinima: number): Drainage {
  const d = terrain.drainage(triangles);
  const r = referenceDrainage(terrain.points, triangles ?? terrain.delaunay().triangles, terrain.maxEdge);
  expect(d.downstream).toBeInstanceOf(Int32Array);
  expect(d.accumulation).toBeInstanceOf(Uint32Array);
  expect(Array.from(d.downstream)).toEqual(r.downstream);
  expect(Array.from(d.basin)).toEqual(r.basin);
  expect(Array.from(d.accumulation)).toEqual(r.accumulation);
  expect(Array.from(d.pits)).toEqual(r.pits);
  expect(Array.from(d.outlets)).toEqual(r.outlets);
  expect(r.localMinima).toBe(localMinima);
  const upstream = new Array<number>(d.downstream.length).fill(0);
  d.downstream.forEach((w, v) => w >= 0 && (upstream[w] += d.accumulation[v]!));
  d.accumulation.forEach((a, v) => a > 0 && expect(a).toBe(1 + upstream[v]!));
  const ends = [...d.pits, ...d.outlets];
  expect(ends.reduce((s, v) => s + d.accumulation[v]!, 0)).toBe(terrain.numPoints);
  for (const b of d.basin) if (b >= 0) expect(ends).toContain(b);
  return d;
}

// Seeded terrains: uniform, DEM-like hills, integer grids with 3 heights (flats
// and equal slopes), and one of them at UTM-like offsets.
function lcg(seed: number) {
  let s = seed;
  return () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
}
function demLike(n: number, seed: number): Float64Array {
  const r = lcg(seed), out: number[] = [];
  for (let i = 0; i < n; i++) {
    const x = r(), y = r();
    out.push(x, y, Math.sin(3 * x) * Math.cos(2.3 * y) + 0.5 * Math.sin(7.1 * x + 5.3 * y) + 0.01 * r());
  }
  return Float64Array.from(out);
}
function flatGrid(w: number, h: number, seed: number, x0 = 0, y0 = 0, cell = 1): Float64Array {
  const r = lcg(seed), out: number[] = [];
  for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) out.push(x0 + cell * i, y0 + cell * j, Math.floor(3 * r()));
  return Float64Array.from(out);
}
const TERRAINS: [string, Float64Array][] = [
  ['random 60', randomPoints(60, 11)],
  ['random 150', randomPoints(150, 12)],
  ['DEM-like 120', demLike(120, 13)],
  ['DEM-like 200', demLike(200, 14)],
  ['flat grid 8x7', flatGrid(8, 7, 15)],
  ['flat grid 10x9', flatGrid(10, 9, 16)],
  ['flat grid at UTM offsets', flatGrid(9, 9, 17, 731012.25, 4100000.5, 30)],
];

describe('terrain.drainage(): the definition, exactly', () => {
  it.each(TERRAINS)('%s: Delaunay, order 1 and orders 2 and 3', (_, xyz) => {
    using terrain = hodt.terrain(xyz);
    checkDrainage(terrain, undefined, terrain.evaluate()['min-local-minima']);
    for (const order of [1, 2, 3]) {
      const s = terrain.solve('min-local-minima', { order });
      checkDrainage(terrain, s.triangles, s.value);
    }
    // Another objective's triangulation too: any triangulation of the points.
    const other = terrain.solve('max-convex-edges', { order: 2 }).triangles;
    checkDrainage(terrain, other, terrain.evaluateTriangles(other)['min-local-minima']);
  });

  it('flat grids have pits that are not local minima (flats), each decided like the reference', () => {
    using terrain = hodt.terrain(flatGrid(10, 9, 16));
    const d = terrain.drainage();
    expect(d.pits.length).toBeGreaterThan(terrain.evaluate()['min-local-minima']);
  });

  it('within a domain, the points at its edge drain out as outlets', () => {
    let turned = 0; // pits that became outlets
    for (const [, xyz] of TERRAINS.slice(0, 4)) {
      using terrain = hodt.terrain(xyz);
      const before = terrain.drainage();
      terrain.maxEdge = 0.12;
      const d = checkDrainage(terrain, undefined, terrain.evaluate()['min-local-minima']);
      expect(Array.from(d.downstream)).toEqual(Array.from(before.downstream)); // water runs as before
      expect(d.pits.length + d.outlets.length).toBe(before.pits.length + before.outlets.length);
      turned += d.outlets.length - before.outlets.length;
      const s = terrain.solve('min-local-minima', { order: 2 });
      checkDrainage(terrain, s.triangles, s.value);
    }
    expect(turned).toBeGreaterThan(0);
  });

  it('a duplicate dropped by dedupe first is no vertex: -1, -1, 0', () => {
    using terrain = hodt.terrain([[0, 0, 5], [4, 0, 6], [4, 4, 7], [0, 4, 8], [2, 2, 1], [2, 2, 3]], { dedupe: 'first' });
    const d = terrain.drainage();
    expect(Array.from(d.downstream)).toEqual([4, 4, 4, 4, -1, -1]);
    expect(Array.from(d.basin)).toEqual([4, 4, 4, 4, 4, -1]);
    expect(Array.from(d.accumulation)).toEqual([1, 1, 1, 1, 5, 0]);
    expect(Array.from(d.pits)).toEqual([4]);
    expect(Array.from(d.outlets)).toEqual([]);
  });

  it('bad triangles: a clear InputError, on one line', () => {
    using terrain = hodt.terrain(randomPoints(20, 3));
    const good = Array.from(terrain.delaunay().triangles);
    const cases: [unknown, RegExp][] = [
      [good.slice(0, -1), /^triangles: \d+ indices is not a multiple of 3$/],
      [[...good.slice(0, -1), 20], /^triangles\[\d+\] is 20, expected a point index from 0 to 19$/],
      [[...good.slice(0, -1), -1], /^triangles\[\d+\] is -1, expected a point index from 0 to 19$/],
      [[...good.slice(0, -1), 1.5], /^triangles\[\d+\] is 1\.5, expected a point index from 0 to 19$/],
      [Uint32Array.from([...good.slice(0, -1), 99]), /^triangle \d+: point 99 is not a vertex of this terrain$/],
      [good.slice(0, -3), /^triangles: [^\n]+$/], // (a triangle missing: a hole)
      ['0 1 2', /^triangles is '0 1 2', expected point indices, three per triangle$/],
    ];
    for (const [triangles, message] of cases) {
      let error: unknown;
      try {
        terrain.drainage(triangles as number[]);
      } catch (e) {
        error = e;
      }
      expect(error).toBeInstanceOf(InputError);
      expect((error as Error).message).toMatch(message);
    }
  });
});

describe('--drainage FILE.geojson', () => {
  const root = new URL('../../', import.meta.url).pathname;
  const run = (cli: 'native' | 'npm', args: string[]) => {
    const r = cli === 'native'
      ? spawnSync(`${root}build/native/hodt`, args, { encoding: 'utf8' })
      : spawnSync('node', [`${root}dist/cli.js`, ...args], { encoding: 'utf8' });
    return { code: r.status, out: r.stdout, err: r.stderr };
  };
  const xyz = demLike(300, 21);
  const points = () => {
    const file = join(dir, 'dem.csv');
    const lines: string[] = [];
    for (let i = 0; i < xyz.length; i += 3) lines.push(`${xyz[i]},${xyz[i + 1]},${xyz[i + 2]}`);
    writeFileSync(file, `x,y,z\n${lines.join('\n')}\n`);
    return file;
  };

  it.each([
    ['stats (Delaunay)', 'stats', [] as string[], undefined],
    ['solve', 'solve', ['--objective', 'min-local-minima'], 1],
    ['solve --order 3', 'solve', ['--objective', 'min-local-minima', '--order', '3'], 3],
  ] as const)('%s: the same file from both CLIs, valid GeoJSON, the counts printed', (_, command, options, order) => {
    const file = points();
    const outputs = (['native', 'npm'] as const).map((cli) => {
      const path = join(dir, `${cli}-${command}-${order ?? 0}.geojson`);
      const r = run(cli, [command, file, ...options, '--crs', 'EPSG:2193', '--drainage', path]);
      expect(r.err).toBe('');
      expect(r.code).toBe(0);
      return { printed: JSON.parse(r.out), text: readFileSync(path, 'utf8') };
    });
    expect(outputs[1]!.text).toBe(outputs[0]!.text);
    const { printed, text } = outputs[0]!;
    expect(getIssues(text)).toEqual([]);
    using terrain = hodt.terrain(xyz);
    const d = order === undefined ? terrain.drainage() : terrain.drainage(terrain.solve('min-local-minima', { order }).triangles);
    expect(printed.drainage).toEqual({ pits: d.pits.length, outlets: d.outlets.length });
    const geojson = JSON.parse(text);
    expect(geojson.crs.properties.name).toBe('urn:ogc:def:crs:EPSG::2193');
    type Feature = { properties: Record<string, number | string>; geometry: { type: string; coordinates: number[][] | number[] } };
    const lines = geojson.features.filter((f: Feature) => f.geometry.type === 'LineString') as Feature[];
    const ends = geojson.features.filter((f: Feature) => f.geometry.type === 'Point') as Feature[];
    expect(lines).toHaveLength(d.downstream.filter((w) => w >= 0).length);
    for (const f of lines) {
      const from = f.properties.from as number, to = f.properties.to as number;
      expect(d.downstream[from]).toBe(to);
      expect(f.properties.accumulation).toBe(d.accumulation[from]);
      expect(f.geometry.coordinates).toEqual([Array.from(xyz.subarray(3 * from, 3 * from + 3)), Array.from(xyz.subarray(3 * to, 3 * to + 3))]);
    }
    expect(ends.filter((f) => f.properties.kind === 'pit').map((f) => f.properties.point)).toEqual(Array.from(d.pits));
    expect(ends.filter((f) => f.properties.kind === 'outlet').map((f) => f.properties.point)).toEqual(Array.from(d.outlets));
    for (const f of ends) {
      expect(f.properties.basinSize).toBe(d.accumulation[f.properties.point as number]);
      expect(f.geometry.coordinates).toEqual(Array.from(xyz.subarray(3 * (f.properties.point as number), 3 * (f.properties.point as number) + 3)));
    }
  });

  it('refuses a file that is not .geojson, in the same words from both CLIs', () => {
    const file = points();
    for (const cli of ['native', 'npm'] as const) {
      const r = run(cli, ['stats', file, '--drainage', join(dir, 'net.json')]);
      expect(r.code).toBe(2);
      expect(r.err).toMatch(/^hodt: --drainage '.*net\.json': the drainage network is GeoJSON; name the file \.geojson\n$/);
    }
  });
});
