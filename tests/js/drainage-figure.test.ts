// The README's drainage picture and tables (scripts/drainage-figure.mjs) are what
// the package computes now: the numbers of pits, outlets, basins and local minima
// of the LiDAR survey and the volcano DEM, recomputed here with the library and
// read back from README.md and docs/api.md, and the picture as the script draws it.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadHodt, type Terrain } from 'hodt';
import { readPointFile } from 'hodt/loaders';
import { describe, expect, test } from 'vitest';
// @ts-expect-error: a plain ES module of the repository's scripts, without types
import { drainageFigure, FIGURE, LIDAR, ORDERS, VOLCANO } from '../../scripts/drainage-figure.mjs';

const repo = fileURLToPath(new URL('../../', import.meta.url));
const read = (f: string) => readFileSync(join(repo, f), 'utf8');

/** The rows of the table between a doc's markers: its numbers, by row name. */
function tableIn(doc: string, name: string): Record<string, number[]> {
  const block = new RegExp(`<!-- ${name}: written by scripts/drainage-figure\\.mjs -->\\n([\\s\\S]*?)\\n<!-- /${name} -->`).exec(read(doc));
  expect(block, `${doc}: the ${name} block`).not.toBeNull();
  const rows: Record<string, number[]> = {};
  for (const line of block![1]!.split('\n').slice(2)) {
    const [label, ...cells] = line.split('|').slice(1, -1).map((c) => c.trim());
    rows[label!] = cells.map(Number);
  }
  return rows;
}

/** Pits, outlets, basins and local minima, as the library gives them, for
 * Delaunay and the fewest local minima at each order. */
function measured(terrain: Terrain): Record<string, number[]> {
  const rows: Record<string, number[]> = {};
  const add = (label: string, triangles: Uint32Array) => {
    const d = terrain.drainage(triangles);
    const basins = new Set(d.basin.filter((b) => b >= 0)).size;
    rows[label] = [d.pits.length, d.outlets.length, basins, terrain.evaluateTriangles(triangles)['min-local-minima']];
  };
  add('Delaunay', terrain.delaunay().triangles);
  for (const k of ORDERS as number[]) {
    const s = terrain.solve('min-local-minima', { order: k });
    expect(s.optimal).toBe(true);
    add(`order ${k}, fewest local minima`, s.triangles);
  }
  return rows;
}

describe('the README drainage figure', async () => {
  const hodt = await loadHodt();
  const cloud = (await readPointFile(readFileSync(join(repo, LIDAR))))!;

  test('the LiDAR table in README.md and docs/api.md is what the library computes', () => {
    using terrain = hodt.terrain(cloud.xyz, { dedupe: 'first' });
    expect(terrain.numPoints).toBe(276);
    const now = measured(terrain);
    expect(tableIn('README.md', 'drainage-lidar')).toEqual(now);
    expect(tableIn('docs/api.md', 'drainage-lidar')).toEqual(now);
    // What the README says of it: the optimum removes pits as the order grows.
    expect(now['order 4, fewest local minima']![0]).toBeLessThan(now['Delaunay']![0]!);
  });

  test('the volcano table is what the library computes: most pits are flats, which the fewest local minima leaves', () => {
    using terrain = hodt.terrain(hodt.readPoints(read(VOLCANO)).points);
    const now = measured(terrain);
    expect(tableIn('README.md', 'drainage-volcano')).toEqual(now);
    for (const [pits, , , minima] of Object.values(now)) expect(pits! > 2 * minima!).toBe(true);
  });

  test('the picture is the one the script draws now, with the counts of the table', async () => {
    const f = await drainageFigure();
    expect(read(FIGURE)).toBe(f.svg);
    const headings = [...f.svg.matchAll(/>(\d+) pits?, (\d+) outlets?, (\d+) basins?; (\d+) local minim/g)].map((m: RegExpMatchArray) => m.slice(1).map(Number));
    const table = tableIn('README.md', 'drainage-lidar');
    expect(headings).toEqual([table['Delaunay'], table['order 4, fewest local minima']]);
  });
});
