// The CLI's files and habits, run as users run it (`node dist/cli.js`, the
// native build): --output in every format read back by independent readers,
// --version, --help, times, --quiet, --progress, and point files as people have
// them. Messages both CLIs print must be identical.
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, loadHodt } from '../../web/src/index.js';
import { float32HalfUlp, readGLB, readOBJ, readPLY } from './meshReaders.js';

const root = new URL('../../', import.meta.url).pathname;
const fixture = (name: string) => `${root}tests/fixtures/${name}`;
const version: string = JSON.parse(readFileSync(`${root}package.json`, 'utf8')).version;

function hodtCli(args: string[], input?: string) {
  const r = spawnSync('node', [`${root}dist/cli.js`, ...args], { encoding: 'utf8', input });
  return { code: r.status, out: r.stdout, err: r.stderr };
}
function native(args: string[]) {
  const r = spawnSync(`${root}build/native/hodt`, args, { encoding: 'utf8' });
  return { code: r.status, out: r.stdout, err: r.stderr };
}
const withoutTimes = (text: string) => {
  const j = JSON.parse(text);
  delete j.timeMs;
  delete j.times;
  return j;
};

let dir: string;
let hodt: Hodt;
const at = (name: string) => join(dir, name);

// UTM-like points as a GIS export writes them: a byte order mark, a header, CR LF,
// a leading '+', exponents, a long decimal; the first point's x is 731012.3456789.
const UTM_TOKENS = [
  ['731012.3456789', '5501234.125', '12.5'],
  ['+731112.5', '5501234.25', '1E+01'],
  ['731062.0669944337466229500000000000000000', '5501334.5', '7.5e0'],
  ['731050', '5501260', '30'],
  ['731090.75', '5501300.125', '2.5E-1'],
  ['731030.5', '5501310', '+18'],
];
const UTM_CSV = `\uFEFFeasting,northing,elevation\r\n${UTM_TOKENS.map((t) => t.join(',')).join('\r\n')}\r\n`;
const UTM_VALUES = UTM_TOKENS.flat().map(Number); // JavaScript's own correctly rounded reading

beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'hodt-cli-output-'));
  writeFileSync(at('utm.csv'), UTM_CSV);
  hodt = await loadHodt();
});
afterAll(() => rmSync(dir, { recursive: true, force: true }));

describe('--output', () => {
  const solveArgs = (...outputs: string[]) => [
    'solve', at('utm.csv'), '--objective', 'max-convex-edges', '--triangles', ...outputs.flatMap((o) => ['--output', at(o)]),
  ];
  let triangles: number[];
  beforeAll(() => {
    const r = hodtCli(solveArgs('tin.obj', 'tin.ply', 'tin.geojson', 'tin.glb', 'tin.json'));
    expect(r.err).toBe('');
    expect(r.code).toBe(0);
    triangles = JSON.parse(r.out).triangles.flat();
    expect(triangles.length).toBeGreaterThan(0);
  });

  it('.obj: the coordinates as read, the triangles of the result', () => {
    const obj = readOBJ(readFileSync(at('tin.obj'), 'utf8'));
    expect(obj.points).toEqual(UTM_VALUES);
    expect(obj.tokens[0]).toBe('731012.3456789');
    expect(obj.triangles).toEqual(triangles);
    expect(obj.comments[0]).toMatch(new RegExp(`^hodt ${version}: max-convex-edges = \\d+ \\(Delaunay \\d+\\), optimal`));
  });

  it('.ply: doubles as read, vertex classes and extrema, faces with the non-Delaunay flag', () => {
    const { vertex, face } = readPLY(readFileSync(at('tin.ply'))).elements;
    expect(vertex!.rows.flatMap((r) => [r.x, r.y, r.z])).toEqual(UTM_VALUES);
    expect(face!.rows.flatMap((r) => r.vertex_indices as number[])).toEqual(triangles);
    // The same measures as the library's, for the same triangulation.
    using terrain = hodt.terrain(Float64Array.from(UTM_VALUES));
    const m = terrain.measuresOfTriangles(Uint32Array.from(triangles));
    expect(vertex!.rows.map((r) => r.class)).toEqual(Array.from(m.vertexClass));
    expect(vertex!.rows.map((r) => r.extremum)).toEqual(Array.from(m.extremum));
    const solved = JSON.parse(hodtCli(solveArgs()).out);
    expect(face!.rows.filter((r) => r.non_delaunay === 1)).toHaveLength(2 * solved.flipped);
  });

  it('.geojson: one polygon per triangle, corners with z exactly as read', () => {
    const doc = JSON.parse(readFileSync(at('tin.geojson'), 'utf8'));
    expect(doc.features).toHaveLength(triangles.length / 3);
    doc.features.forEach((f: any, k: number) => {
      const ring: number[][] = f.geometry.coordinates[0];
      const corners = triangles.slice(3 * k, 3 * k + 3).map((i) => UTM_VALUES.slice(3 * i, 3 * i + 3));
      expect(ring.slice(0, 3).sort()).toEqual(corners.sort());
      expect(f.properties.index).toBe(k);
    });
    expect(readFileSync(at('tin.geojson'), 'utf8')).toContain('[731012.3456789,5501234.125,12.5]');
  });

  it('.glb: float32 offsets from the node translation, as exact as float32 allows', () => {
    const { gltf, accessor } = readGLB(readFileSync(at('tin.glb')));
    const [primitive] = gltf.meshes[0].primitives;
    expect(gltf.accessors[primitive.attributes.POSITION].count).toBe(UTM_VALUES.length / 3);
    expect(accessor(primitive.indices)).toEqual(triangles);
    const t: number[] = gltf.nodes.find((n: any) => n.mesh === 0).translation;
    const positions = accessor(primitive.attributes.POSITION);
    UTM_VALUES.forEach((v, i) => {
      expect(Math.abs(positions[i]! - (v - t[i % 3]!))).toBeLessThanOrEqual(float32HalfUlp(v - t[i % 3]!));
    });
  });

  it('.json: the printed result plus the triangles, the same from the native CLI', () => {
    const written = JSON.parse(readFileSync(at('tin.json'), 'utf8'));
    expect(written.triangles.flat()).toEqual(triangles);
    expect(Object.keys(written.times)).toEqual(['readMs', 'buildMs', 'solveMs']);
    const n = native(['solve', at('utm.csv'), '--objective', 'max-convex-edges', '--output', at('native.json')]);
    expect(n.err).toBe('');
    expect(withoutTimes(readFileSync(at('native.json'), 'utf8'))).toEqual(withoutTimes(JSON.stringify(written)));
    // stats writes the Delaunay triangulation.
    hodtCli(['stats', at('utm.csv'), '--output', at('stats.json'), '--output', at('stats.obj')]);
    const stats = JSON.parse(readFileSync(at('stats.json'), 'utf8'));
    expect(stats.delaunayTriangles).toHaveLength(stats.triangles);
    expect(readOBJ(readFileSync(at('stats.obj'), 'utf8')).triangles).toEqual(stats.delaunayTriangles.flat());
  });

  it('the native CLI writes .json only and says where the other formats are', () => {
    const r = native(['solve', at('utm.csv'), '--objective', 'min-local-minima', '--output', at('n.ply')]);
    expect(r.code).toBe(2);
    expect(r.err).toBe(`hodt: --output '${at('n.ply')}': this build of hodt writes .json only; for .ply use the npm CLI: npx hodt\n`);
  });

  it.each([
    ['an unknown format', () => ['--output', 'tin.xyz'], /^hodt: --output 'tin\.xyz': unknown format; name the file \.json, \.obj, \.ply, \.geojson or \.glb\n$/],
    ['no extension', () => ['--output', 'tin'], /unknown format/],
    ['a missing value', () => ['--output'], /^hodt: --output needs a value\n$/],
    ['a missing directory', () => ['--output', at('missing/tin.json')], /^hodt: cannot write .*\/missing\/tin\.json: no such directory\n$/],
    ['a directory', () => ['--output', at('folder.json')], /^hodt: cannot write .*\/folder\.json: is a directory\n$/],
  ])('refuses %s with the same one line from both CLIs', (_name, output, message) => {
    mkdirSync(at('folder.json'), { recursive: true });
    const args = ['stats', fixture('uniform-12.csv'), ...output()];
    const w = hodtCli(args), n = native(args);
    expect(w.code).toBe(2);
    expect(w.out).toBe('');
    expect(w.err).toMatch(message);
    expect(n).toEqual(w);
  });
});

describe('--version and --help', () => {
  it('--version prints the package version, the same from both CLIs', () => {
    expect(hodtCli(['--version'])).toEqual({ code: 0, out: `hodt ${version}\n`, err: '' });
    expect(native(['--version'])).toEqual(hodtCli(['--version']));
  });

  it('--help names every option and every objective with its meaning and unit', () => {
    const help = hodtCli(['--help']);
    expect(help.code).toBe(0);
    expect(native(['--help'])).toEqual(help);
    for (const option of ['--objective', '--method', '--epsilon', '--order', '--triangles', '--trace', '--dedupe', '--output', '--quiet', '--progress']) {
      expect(help.out).toContain(`  ${option} `);
    }
    const units: Record<string, RegExp> = {
      'max-convex-vertices': /count/, 'min-local-minima': /count/, 'min-local-extrema': /count/, 'max-convex-edges': /count/,
      'min-mixed-vertices': /count/, 'minmax-degree': /count/,
      'minmax-edge-area-ratio': /ratio/, 'minmax-vertex-area-ratio': /ratio/,
      'minmax-edge-normal-angle': /radians/, 'minmax-vertex-normal-angle': /radians/,
      'minmax-edge-enclosing-circle': /^plane units/, 'min-total-edge-length': /^plane units/, 'minmax-triangle-area': /^squared plane units/,
    };
    for (const o of hodt.objectives) {
      const line = help.out.split('\n').findIndex((l) => l.startsWith(`  ${o.id} [`));
      expect(line, o.id).toBeGreaterThan(0);
      const [, unit] = /\[(.*)\]$/.exec(help.out.split('\n')[line]!)!;
      expect(unit, o.id).toMatch(units[o.id]!);
      expect(unit, o.id).toBe(o.unit);
      // The rest of the core's objective table, as the bindings give it.
      expect(o.combine, o.id).toBe(o.id.startsWith('minmax-') ? 'max' : 'sum');
      expect(o.polynomial, o.id).toBe(!['max-convex-edges', 'min-mixed-vertices', 'minmax-degree'].includes(o.id));
      expect(o.reference.startsWith('NP-hard'), o.id).toBe(!o.polynomial);
      expect(help.out.split('\n')[line + 1]!.trim()).toBe(o.summary);
    }
  });
});

describe('times, --quiet, --progress', () => {
  it('solve reports read, build and solve times next to timeMs', () => {
    const j = JSON.parse(hodtCli(['solve', fixture('uniform-300.csv'), '--objective', 'min-local-minima']).out);
    expect(Object.keys(j.times)).toEqual(['readMs', 'buildMs', 'solveMs']);
    for (const v of Object.values(j.times) as number[]) expect(v).toBeGreaterThanOrEqual(0);
    expect(j.times.solveMs).toBeGreaterThanOrEqual(j.timeMs * 0.99);
  });

  it('warns about dropped duplicates unless --quiet, the same from both CLIs', () => {
    const args = ['stats', fixture('bad-duplicate.csv'), '--dedupe', 'first'];
    const w = hodtCli(args);
    expect(w.code).toBe(0);
    expect(w.err).toMatch(/^hodt: warning: .*bad-duplicate\.csv: dropped 1 point at the same \(x, y\) as an earlier one \(--dedupe first\)\n$/);
    expect(native(args)).toEqual(w);
    const quiet = hodtCli([...args, '--quiet']);
    expect(quiet.err).toBe('');
    expect(quiet.out).toBe(w.out);
  });

  it('--progress names each step on stderr, the same from both CLIs; --quiet excludes it', () => {
    const args = ['solve', fixture('uniform-50.csv'), '--objective', 'max-convex-edges', '--output', at('p.json'), '--progress'];
    // (The front end's steps: the solve's own phases come as they take time.)
    const steps = (err: string) => err.split('\n').filter((l) => l !== '' && !/^hodt: [a-z ]+ \(max-convex-edges\)./.test(l));
    const w = hodtCli(args);
    expect(w.code).toBe(0);
    expect(steps(w.err)).toEqual([
      `hodt: reading ${fixture('uniform-50.csv')}`,
      'hodt: triangulating 50 points',
      'hodt: solving (max-convex-edges)',
      `hodt: writing ${at('p.json')}`,
    ]);
    expect(steps(native(args).err)).toEqual(steps(w.err));
    const both = hodtCli([...args, '--quiet']);
    expect(both).toMatchObject({ code: 2, out: '', err: 'hodt: --quiet and --progress exclude each other\n' });
    expect(native([...args, '--quiet'])).toEqual(both);
  });

  it('on a terminal: nothing for a short run; with --progress, drawn in place and cleared at the end', () => {
    const read = (path: string) => readFileSync(path);
    const shown: string[] = [];
    const io = { progress: (t: string) => shown.push(t), stderrIsTerminal: true };
    const args = ['solve', fixture('uniform-50.csv'), '--objective', 'min-local-minima'];
    expect(hodt.runCli(args, read, io).exitCode).toBe(0);
    expect(shown).toEqual([]); // under a second
    hodt.runCli([...args, '--progress'], read, io);
    expect(shown.length).toBeGreaterThanOrEqual(4);
    for (const t of shown.slice(0, -1)) expect(t).toMatch(/^\r\x1b\[Khodt: /);
    expect(shown.at(-1)).toBe('\r\x1b[K');
  });

  it('--progress on a real solve: the phases by name, each percentage never going back, an estimate once it means something', () => {
    // 39 points, 16 flippable quads: brute force over 65,536 triangulations, a
    // phase that knows its size, redrawn every 0.1 s on a terminal.
    const points = at('brute-39.csv');
    writeFileSync(points, readFileSync(fixture('uniform-50.csv'), 'utf8').split('\n').slice(0, 40).join('\n'));
    const shown: string[] = [];
    const io = { progress: (t: string) => shown.push(t), stderrIsTerminal: true };
    const args = ['solve', points, '--objective', 'min-mixed-vertices', '--method', 'brute-force', '--progress'];
    expect(hodt.runCli(args, (path) => readFileSync(path), io).exitCode).toBe(0);
    const lines = shown.map((t) => t.replace(/^\r\x1b\[K/, '')).filter((l) => l !== '');
    expect(lines.slice(0, 3)).toEqual([`hodt: reading ${points}`, 'hodt: triangulating 39 points', 'hodt: solving (min-mixed-vertices)']);
    const named = /^hodt: (finding the regions|solving exactly|approximating|searching|proving a bound|measuring|solving) \(min-mixed-vertices\)(: (\d+)%(, about \d+ (s|min) left)?|: \d+ s so far)?$/;
    const percents = new Map<string, number>();
    let sized = 0;
    for (const line of lines.slice(3)) {
      const m = named.exec(line);
      expect(m, line).not.toBeNull();
      if (m![3] === undefined) continue;
      const percent = Number(m![3]);
      expect(percent).toBeGreaterThanOrEqual(percents.get(m![1]!) ?? 0);
      expect(percent).toBeLessThanOrEqual(100);
      percents.set(m![1]!, percent);
      ++sized;
    }
    expect(sized).toBeGreaterThanOrEqual(2);
    expect(percents.has('solving exactly')).toBe(true);
  });
});

describe('point files as people have them', () => {
  const variants: [string, string | Uint8Array][] = [
    ['BOM and CR LF', UTM_CSV],
    ['CR only', UTM_CSV.replaceAll('\r\n', '\r')],
    ['LF, no BOM', UTM_CSV.slice(1).replaceAll('\r\n', '\n')],
    ['UTF-16 LE', new Uint8Array(Buffer.from(`\uFEFF${UTM_CSV.slice(1)}`, 'utf16le'))],
  ];
  it.each(variants)('%s: both CLIs read the same points, exactly', (name, content) => {
    const file = at(`${name.replace(/\W+/g, '-')}.csv`);
    writeFileSync(file, content);
    const args = ['stats', file, '--output', at('variant.json')];
    const w = hodtCli(args);
    expect(w.err).toBe('');
    expect(JSON.parse(w.out).points).toBe(6);
    expect(native(args)).toEqual(w);
    expect(Array.from(hodt.readPoints(content, name).points)).toEqual(UTM_VALUES);
    hodtCli(['stats', file, '--output', at('variant.obj')]);
    expect(readOBJ(readFileSync(at('variant.obj'), 'utf8')).points).toEqual(UTM_VALUES);
  });

  it('read errors are worded the same by both CLIs', () => {
    for (const args of [['stats', fixture('no-such-file.csv')], ['stats', dir]]) {
      const w = hodtCli(args);
      expect(w.code).toBe(2);
      expect(native(args)).toEqual(w);
    }
    expect(hodtCli(['stats', dir]).err).toBe(`hodt: ${dir}: is a directory\n`);
  });
});
