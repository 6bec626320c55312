// Objectives: switching changes the highlighted flips, and the page's values
// equal the CLI's on the points the page exports (exact doubles both ways).
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { loadHodt, type Hodt } from 'hodt';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { readGLB, readOBJ, readPLY } from '../js/meshReaders.ts';
import { hooks, openPage, screenshot, settled, startDemo, type Demo } from './harness.ts';

let demo: Demo;
let hodt: Hodt;
beforeAll(async () => {
  demo = await startDemo();
  hodt = await loadHodt();
});
afterAll(async () => {
  await demo?.close();
});

/** `hodt solve FILE --objective ID --method exact`: the CLI (core/src/cli/cli.cpp) run
 * in-process exactly as the npm bin runs it, reading the file from disk (not
 * dist/cli.js itself, which a concurrent build may be rewriting). */
function cli(file: string, objective: string) {
  const r = hodt.runCli(['solve', file, '--objective', objective, '--method', 'exact'], (p) => readFileSync(p, 'utf8'));
  if (r.exitCode !== 0) throw new Error(`hodt solve failed (${r.exitCode}): ${r.stderr}`);
  return JSON.parse(r.stdout);
}

describe('objectives', () => {
  test('switching objective changes the flips; values equal the CLI on the exported points', async () => {
    const { page, context, errors } = await openPage(demo);
    let h = await hooks(page);
    await page.selectOption('#method', 'exact');
    await settled(page, h.solves);

    // The points CSV the page exports (through the real download).
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-csv')]);
    const dir = mkdtempSync(`${tmpdir()}/hodt-e2e-`);
    const file = `${dir}/points.csv`;
    await download.saveAs(file);
    h = await hooks(page);
    expect(readFileSync(file, 'utf8')).toBe(h.pointsCsv);

    const choices = new Map<string, string>();
    for (const id of ['min-total-edge-length', 'max-convex-vertices', 'minmax-edge-normal-angle', 'min-mixed-vertices']) {
      const before = (await hooks(page)).solves;
      await page.selectOption('#objective', id);
      await settled(page, before);
      h = await hooks(page);
      expect(h.objective).toBe(id);
      const mine = h.solution!;
      const theirs = cli(file, id);
      expect(mine.value, id).toBe(theirs.value);
      expect(mine.delaunayValue, id).toBe(theirs.delaunayValue);
      expect(mine.optimal, id).toBe(theirs.optimal);
      expect(mine.flipped, id).toBe(theirs.flipped);
      expect(Object.keys(mine).slice(0, 9)).toEqual(Object.keys(theirs).slice(0, 9));
      expect(h.flipped).toBe(mine.flipped);
      expect(Number(await page.locator('#result-value').getAttribute('data-value'))).toBe(theirs.value);
      expect(await page.locator('#measures tr.active').getAttribute('data-id')).toBe(id);
      choices.set(id, h.choice);
    }
    expect(new Set(choices.values()).size).toBe(choices.size); // each objective flips differently

    // The solution JSON download is the CLI's document (up to the time taken and
    // the CLI's own read, build and solve times).
    const [json] = await Promise.all([page.waitForEvent('download'), page.click('#export-json')]);
    await json.saveAs(`${dir}/solution.json`);
    const saved = JSON.parse(readFileSync(`${dir}/solution.json`, 'utf8'));
    const { times: _times, ...expected } = cli(file, 'min-mixed-vertices');
    expect({ ...saved, timeMs: 0 }).toEqual({ ...expected, timeMs: 0 });

    // The mesh downloads (hodt/export's writers) hold the shown triangulation.
    const meshes: Record<string, Buffer> = {};
    for (const format of ['obj', 'ply', 'geojson', 'glb']) {
      const [d] = await Promise.all([page.waitForEvent('download'), page.click(`#export-${format}`)]);
      expect(d.suggestedFilename()).toBe(`hodt-min-mixed-vertices.${format}`);
      await d.saveAs(`${dir}/tin.${format}`);
      meshes[format] = readFileSync(`${dir}/tin.${format}`);
    }
    const numPoints = h.points;
    expect(readOBJ(meshes.obj!.toString('utf8')).points).toHaveLength(3 * numPoints);
    expect(readPLY(new Uint8Array(meshes.ply!)).elements.face!.rows.filter((r) => r.non_delaunay === 1)).toHaveLength(2 * h.flipped);
    expect(JSON.parse(meshes.geojson!.toString('utf8')).features).toHaveLength(h.triangles);
    expect(readGLB(new Uint8Array(meshes.glb!)).gltf.accessors[0].count).toBe(numPoints);
    await screenshot(page, 'demo-objective.png');
    expect(errors).toEqual([]);
    await context.close();
  });

  test('a long solve shows progress, the page stays responsive, and Cancel stops it', async () => {
    const { page, context, errors } = await openPage(demo);
    // 50 random points with 23 flippable quads: brute force tries 2^23
    // triangulations, minutes of work.
    await page.setInputFiles('#import-file', { name: 'slow.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(randomPoints(50, 5))) });
    await page.waitForFunction(() => window.__hodt!.points === 50);
    expect((await hooks(page)).quads).toBe(23);
    await page.selectOption('#objective', 'min-mixed-vertices');
    await page.selectOption('#method', 'brute-force');
    await page.waitForFunction(() => window.__hodt!.solving);
    await page.waitForTimeout(1000);
    expect((await hooks(page)).solving).toBe(true);
    expect(await page.locator('#progress').isVisible()).toBe(true);
    expect(await page.locator('.elapsed').textContent()).toMatch(/^[1-9]\.\d s$/);
    // Brute force knows its size: the phase by name, a share, a time left once it has one.
    await page.waitForFunction(() => document.querySelector('#phase')?.textContent?.startsWith('solving exactly'));
    expect(await page.locator('#progress').getAttribute('data-determinate')).toBe('');
    expect(Number(await page.locator('#progress').getAttribute('aria-valuenow'))).toBeGreaterThanOrEqual(0);
    // The page answers while the worker computes: switch views and back.
    await page.click('.segmented button[data-view="plan"]');
    expect(await page.locator('.stage').getAttribute('data-view')).toBe('plan');
    await page.click('.segmented button[data-view="split"]');
    await screenshot(page, 'demo-solving.png');

    const before = (await hooks(page)).solves;
    await page.click('#cancel');
    await settled(page, before);
    expect(await page.locator('#result').getAttribute('data-state')).toBe('cancelled');
    expect((await hooks(page)).flipped).toBe(0); // back to Delaunay

    // The restarted worker solves the next request.
    await page.selectOption('#method', 'exact');
    await settled(page, before + 1);
    expect(await page.locator('#result').getAttribute('data-state')).toBe('solved');
    expect(errors).toEqual([]);
    await context.close();
  });
});

/** Deterministic random points (mulberry32), as [[x, y, z], ...]. */
function randomPoints(n: number, seed: number): number[][] {
  let s = seed >>> 0;
  const random = () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return Array.from({ length: n }, () => [random() * 100, random() * 100, random() * 12]);
}
