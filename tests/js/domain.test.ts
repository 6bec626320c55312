// The domain (maxEdge) through every surface: the API option and property,
// per-triangle inside flags, solves that equal brute force within the domain,
// and the CLIs' raster default on a DEM whose NODATA inlet the hull bridges.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, InputError, loadHodt, OBJECTIVE_IDS } from '../../web/src/index.js';
import { readPLY } from './meshReaders.js';
import { randomPoints } from './randomPoints.js';

const root = new URL('../../', import.meta.url).pathname;
const inlet = (ext: string) => `${root}tests/fixtures-gis/dem-utm-inlet-nodata.${ext}`;

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

describe('the domain in the API', () => {
  it('is a terrain option and property, checked, and changes what is measured', () => {
    const points = randomPoints(60, 7);
    const plain = hodt.terrain(points);
    const t = hodt.terrain(points, { maxEdge: 0.2 });
    expect(plain.maxEdge).toBeNull();
    expect(t.maxEdge).toBe(0.2);
    const inside = t.measures().inside;
    expect(inside.length).toBe(t.delaunay().triangles.length / 3);
    expect(inside.includes(0)).toBe(true);
    expect(plain.measures().inside.every((v) => v === 1)).toBe(true);
    expect(t.delaunayValues()['min-total-edge-length']).toBeLessThan(plain.delaunayValues()['min-total-edge-length']);
    for (const bad of [0, -1, Number.NaN, 'far' as unknown as number]) {
      expect(() => hodt.terrain(points, { maxEdge: bad })).toThrow(InputError);
      expect(() => (t.maxEdge = bad)).toThrow(/maxEdge/);
    }
    expect(t.maxEdge).toBe(0.2); // (a refused value changes nothing)
    t.maxEdge = null;
    expect(t.delaunayValues()).toEqual(plain.delaunayValues());
    t.dispose();
    plain.dispose();
  });

  it('warns when it leaves (almost) every triangle outside, naming the count and the spacing', () => {
    const points = randomPoints(200, 3); // in the unit square: spacing about 0.07
    const t = hodt.terrain(points, { maxEdge: 0.001 });
    expect(t.warnings.length).toBe(1);
    expect(t.warnings[0]).toMatch(/leaves 0 of \d+ triangles inside to be measured/);
    expect(t.warnings[0]).toMatch(/median Delaunay edge length\) is 0\.0\d+/);
    t.maxEdge = 0.5;
    expect(t.warnings).toEqual([]);
    t.maxEdge = null;
    expect(t.warnings).toEqual([]);
    t.dispose();
    const r = spawnSync('node', [`${root}dist/cli.js`, 'solve', inlet('asc'), '--objective', 'min-local-minima', '--max-edge', '1'], {
      encoding: 'utf8',
    });
    expect(r.status).toBe(0);
    expect(r.stderr).toMatch(/warning: .*inlet-nodata\.asc: the domain \(maxEdge 1\) leaves 0 of \d+ triangles inside.* is 2\.5/);
  });

  it('every objective, order 1 and 2, equals brute force within the domain', () => {
    let differs = 0;
    for (let seed = 1; seed <= 12; ++seed) {
      const points = randomPoints(9, seed);
      const t = hodt.terrain(points, { maxEdge: 0.45 });
      const plain = hodt.terrain(points);
      for (const order of [1, 2]) {
        for (const id of OBJECTIVE_IDS) {
          const want = t.solve(id, { method: 'brute-force', order });
          const got = t.solve(id, { method: 'exact', order });
          expect(got.optimal).toBe(true);
          expect(got.value).toBeCloseTo(want.value, 12);
          expect(t.evaluateTriangles(got.triangles)[id]).toBe(got.value);
          if (plain.solve(id, { method: 'brute-force', order }).value !== want.value) ++differs;
        }
      }
      t.dispose();
      plain.dispose();
    }
    expect(differs).toBeGreaterThan(10);
  });
});

describe('the raster default in the CLIs', () => {
  const dir = mkdtempSync(join(tmpdir(), 'hodt-domain-'));
  const run = (cmd: string, args: string[]) => spawnSync(cmd, args, { encoding: 'utf8' });
  const npm = (args: string[]) => run('node', [`${root}dist/cli.js`, ...args]);

  it('leaves triangles across NODATA outside and then flips quads the hull slivers hid', () => {
    for (const [cli, file] of [
      [npm, inlet('tif')],
      [npm, inlet('asc')],
      [(a: string[]) => run(`${root}build/native/hodt`, a), inlet('asc')],
    ] as const) {
      const ply = join(dir, 'tin.ply');
      const args = ['solve', file, '--objective', 'minmax-edge-normal-angle'];
      const r = cli(cli === npm ? [...args, '--output', ply] : args);
      expect(r.status).toBe(0);
      expect(r.stderr).toMatch(/triangles with an edge longer than 7\.5 \(3 cells\) are outside the domain/);
      const s = JSON.parse(r.stdout);
      expect(s.maxEdge).toBe(7.5);
      expect(s.outsideTriangles).toBeGreaterThan(10);
      expect(s.flipped).toBeGreaterThan(0);
      expect(s.value).toBeLessThan(s.delaunayValue);
      const none = JSON.parse(cli([...args, '--max-edge', 'none']).stdout);
      expect(none.maxEdge).toBeUndefined();
      expect(none.value).toBeGreaterThan(s.value);
      if (cli === npm) {
        const faces = readPLY(new Uint8Array(readFileSync(ply))).elements.face!;
        const outside = faces.rows.map((f) => f.outside);
        expect(outside.filter((o) => o === 1).length).toBe(s.outsideTriangles);
      }
    }
  });

  it('prints the loaders\' and the core\'s notes once the input is read, before the solve', () => {
    const r = npm(['solve', inlet('tif'), '--objective', 'min-local-minima', '--progress']);
    expect(r.status).toBe(0);
    const solving = r.stderr.indexOf('hodt: solving (min-local-minima)');
    expect(solving).toBeGreaterThan(0);
    expect(r.stderr.indexOf('are outside the domain')).toBeGreaterThan(r.stderr.indexOf('hodt: triangulating'));
    expect(r.stderr.indexOf('are outside the domain')).toBeLessThan(solving);
    expect(r.stderr.indexOf('coordinates in EPSG:32633, kept as read')).toBeGreaterThan(0);
    expect(r.stderr.indexOf('coordinates in EPSG:32633, kept as read')).toBeLessThan(solving);
    expect(r.stderr.match(/are outside the domain/g)?.length).toBe(1);
  });

  it('readPoints gives an ASCII grid with NODATA its default domain, and other files none', () => {
    expect(hodt.readPoints(new Uint8Array(readFileSync(inlet('asc'))), 'inlet.asc').maxEdge).toBe(7.5);
    expect(hodt.readPoints('0 0 0\n1 0 0\n0 1 1\n').maxEdge).toBeUndefined();
  });

  it('rejects a --max-edge that is not a positive length', () => {
    for (const bad of ['0', '-2', 'far']) {
      const r = npm(['stats', inlet('asc'), '--max-edge', bad]);
      expect(r.status).toBe(2);
      expect(r.stderr).toMatch(/--max-edge/);
    }
  });

  it('cleans up', () => rmSync(dir, { recursive: true }));
});
