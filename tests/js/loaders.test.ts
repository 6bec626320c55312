// GIS files in (hodt/loaders and the npm CLI): GeoTIFF DEMs made by GDAL from
// one ASCII grid (Int16 + LZW stripped, Float32 + DEFLATE tiled, Float64
// PixelIsPoint) give exactly that grid's points; a LAS file and its LAZ give the
// same points; binary files the native build cannot read are named, not parsed.
// Fixtures: tests/fixtures-gis/README.md says where each comes from.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { readGeoTIFF, readLAS, readPointFile, sniffFormat } from '../../web/src/loaders/index.js';

const root = new URL('../../', import.meta.url).pathname;
const gis = (name: string) => `${root}tests/fixtures-gis/${name}`;
const bytes = (name: string) => new Uint8Array(readFileSync(gis(name)));

function run(cmd: string[], args: string[]) {
  const r = spawnSync(cmd[0]!, [...cmd.slice(1), ...args], { encoding: 'utf8' });
  return { code: r.status, out: r.stdout, err: r.stderr };
}
const npmCli = (args: string[]) => run(['node', `${root}dist/cli.js`], args);
const native = (args: string[]) => run([`${root}build/native/hodt`], args);

// The grid's points computed from its header: cell centres, NODATA skipped.
function gridPoints(text: string): number[][] {
  const lines = text.trim().split('\n');
  const header = new Map(lines.slice(0, 6).map((l) => [l.split(/\s+/)[0]!.toLowerCase(), Number(l.split(/\s+/)[1])]));
  const [nrows, cell] = [header.get('nrows')!, header.get('cellsize')!];
  const [x0, y0, nodata] = [header.get('xllcorner')!, header.get('yllcorner')!, header.get('nodata_value')!];
  const points: number[][] = [];
  lines.slice(6).forEach((line, r) =>
    line.trim().split(/\s+/).forEach((v, c) => {
      if (Number(v) !== nodata) points.push([x0 + (c + 0.5) * cell, y0 + (nrows - r - 0.5) * cell, Number(v)]);
    }),
  );
  return points;
}
const triples = (xyz: Float64Array) => Array.from({ length: xyz.length / 3 }, (_, i) => [xyz[3 * i]!, xyz[3 * i + 1]!, xyz[3 * i + 2]!]);
const sorted = (p: number[][]) => [...p].sort((a, b) => a[0]! - b[0]! || a[1]! - b[1]! || a[2]! - b[2]!);

describe('GeoTIFF', () => {
  const expected = sorted(gridPoints(readFileSync(gis('dem-utm-40x30.asc'), 'utf8')));
  for (const name of ['dem-utm-int16-lzw.tif', 'dem-utm-float32-tiled-deflate.tif', 'dem-utm-float64-pixel-is-point.tif']) {
    it(`${name}: exactly the grid's cell centres and heights, NODATA skipped, the CRS kept`, async () => {
      expect(sniffFormat(bytes(name))).toBe('geotiff');
      const cloud = await readGeoTIFF(bytes(name));
      expect(sorted(triples(cloud.xyz))).toEqual(expected);
      expect(cloud.crs).toBe('EPSG:32633');
      expect(cloud.warnings.join()).toContain('skipped 31 of 1200 cells');
    });
  }

  it('the npm CLI solves a GeoTIFF as it solves the same grid as text', () => {
    const strip = (out: string) => {
      const j = JSON.parse(out);
      delete j.timeMs;
      delete j.times;
      delete j.crs; // (the GeoTIFF names one, the grid has no .prj)
      return j;
    };
    const args = ['--objective', 'min-local-minima'];
    const tif = npmCli(['solve', gis('dem-utm-float32-tiled-deflate.tif'), ...args]);
    const asc = npmCli(['solve', gis('dem-utm-40x30.asc'), ...args]);
    expect(tif.code).toBe(0);
    expect(strip(tif.out)).toEqual(strip(asc.out));
    expect(tif.err).toContain('coordinates in EPSG:32633');
    expect(JSON.parse(tif.out).crs).toBe('EPSG:32633');
    expect(JSON.parse(asc.out).crs).toBeUndefined();
    expect(npmCli(['solve', gis('dem-utm-int16-lzw.tif'), ...args, '--quiet']).err).toBe('');
  });

  it('writes the TIN of a GeoTIFF', () => {
    const dir = mkdtempSync(join(tmpdir(), 'hodt-loaders-'));
    try {
      const out = join(dir, 'tin.geojson');
      const json = join(dir, 'tin.json');
      const r = npmCli(['solve', gis('dem-utm-int16-lzw.tif'), '--objective', 'max-convex-edges', '--output', out, '--output', json, '--quiet']);
      expect(r.code).toBe(0);
      expect(JSON.parse(readFileSync(json, 'utf8')).crs).toBe('EPSG:32633');
      const features = JSON.parse(readFileSync(out, 'utf8')).features;
      expect(features.length).toBe(JSON.parse(r.out).triangles ?? features.length);
      expect(features[0].geometry.coordinates[0][0][0]).toBeGreaterThan(500000);
      expect(JSON.parse(readFileSync(out, 'utf8')).crs).toEqual({ type: 'name', properties: { name: 'urn:ogc:def:crs:EPSG::32633' } });
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });

  it("keeps an ASCII grid's .prj sidecar (ESRI's habit) in every output", () => {
    const dir = mkdtempSync(join(tmpdir(), 'hodt-loaders-'));
    try {
      writeFileSync(join(dir, 'dem.asc'), bytes('dem-utm-40x30.asc'));
      writeFileSync(join(dir, 'dem.prj'), 'PROJCS["WGS 84 / UTM zone 33N",GEOGCS["WGS 84",AUTHORITY["EPSG","4326"]],AUTHORITY["EPSG","32633"]]');
      const ply = join(dir, 'tin.ply');
      const r = npmCli(['solve', join(dir, 'dem.asc'), '--objective', 'min-local-minima', '--output', ply]);
      expect(r.code).toBe(0);
      expect(JSON.parse(r.out).crs).toBe('EPSG:32633');
      expect(r.err).toContain(`coordinates in EPSG:32633 of ${join(dir, 'dem.prj')}`);
      expect(readFileSync(ply).subarray(0, 400).toString('latin1')).toContain('\ncomment crs EPSG:32633\n');
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });

  it('a truncated GeoTIFF is one line naming the file, exit 2', () => {
    const dir = mkdtempSync(join(tmpdir(), 'hodt-loaders-'));
    try {
      const cut = join(dir, 'cut.tif');
      writeFileSync(cut, bytes('dem-utm-float32-tiled-deflate.tif').subarray(0, 600));
      const r = npmCli(['stats', cut]);
      expect(r.code).toBe(2);
      expect(r.err.trim().split('\n')).toHaveLength(1);
      expect(r.err).toContain(`hodt: ${cut}: `);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});

describe('LAS and LAZ', () => {
  it('a LAS file and its LAZ give the same points; ground by default, every class on request', async () => {
    const las = await readLAS(bytes('lidar-point10.las'));
    const laz = await readLAS(bytes('lidar-point10.laz'));
    expect(laz.xyz).toEqual(las.xyz);
    expect(las.xyz.length / 3).toBe(276);
    expect(las.crs).toBe('EPSG:26910');
    const all = await readLAS(bytes('lidar-point10.laz'), { classes: 'all' });
    expect(all.xyz.length / 3).toBe(1065);
    expect(all.warnings).toEqual([]);
    // LAS 1.4, another point format, the same survey.
    const v14 = await readPointFile(bytes('lidar-point-time-1.4.laz'), { classes: 'all' });
    expect(v14!.xyz).toEqual(all.xyz);
    expect(Array.from(all.xyz).every(Number.isFinite)).toBe(true);
  });

  it('the npm CLI reads LAZ (duplicates kept first), and --classes all', () => {
    const ground = npmCli(['stats', gis('lidar-point10.laz')]);
    expect(ground.code).toBe(0);
    expect(JSON.parse(ground.out).points).toBe(276);
    expect(ground.err).toContain('read 276 ground points (class 2) of 1065');
    const all = npmCli(['stats', gis('lidar-point10.laz'), '--classes', 'all', '--quiet']);
    expect(all.code).toBe(0);
    expect(JSON.parse(all.out).points).toBeGreaterThan(276);
    expect(npmCli(['stats', gis('lidar-point10.laz'), '--classes', 'some']).err).toContain(
      "--classes expects 'ground' or 'all', got 'some'",
    );
  });

  it('a truncated LAS file is one clear line', async () => {
    const cut = bytes('lidar-point10.las').subarray(0, 2000);
    await expect(readLAS(cut)).rejects.toThrow(/^LAS: the header promises 1065 points of 20 bytes from byte \d+; the file has 2000 bytes, room for \d+$/);
  });
});

describe('binary files the native build does not read', () => {
  for (const [name, what] of [
    ['dem-utm-int16-lzw.tif', 'a TIFF/GeoTIFF raster, not text'],
    ['lidar-point10.laz', 'a LAS/LAZ point cloud, not text'],
  ] as const) {
    it(`${name}: named in one line, exit 2`, () => {
      const r = native(['stats', gis(name)]);
      expect(r.code).toBe(2);
      expect(r.err.trim().split('\n')).toEqual([`hodt: ${gis(name)}: ${what}; the npm CLI (npx hodt) and hodt/loaders read ${name.endsWith('.tif') ? 'GeoTIFF DEMs' : 'LAS and LAZ'}`]);
    });
  }
});

describe('text habits of GIS users', () => {
  it('--nodata V drops the gaps of an XYZ export', () => {
    const input = '0 0 5\n1 0 -9999\n0 1 6\n1 1 7\n2 2 -9999\n';
    const r = spawnSync('node', [`${root}dist/cli.js`, 'stats', '-', '--nodata', '-9999'], { encoding: 'utf8', input });
    expect(r.status).toBe(0);
    expect(JSON.parse(r.stdout).points).toBe(3);
  });

  it('x and y in degrees under heights in metres: a warning, in both CLIs', () => {
    const input = '10.1 50.1 500\n10.2 50.1 900\n10.1 50.2 300\n10.2 50.25 1200\n';
    const w = spawnSync('node', [`${root}dist/cli.js`, 'stats', '-'], { encoding: 'utf8', input });
    const n = spawnSync(`${root}build/native/hodt`, ['stats', '-'], { encoding: 'utf8', input });
    expect(w.stderr).toContain('x and y look like degrees (longitude, latitude) while z spans 900');
    expect(n.stderr).toBe(w.stderr);
  });
});
