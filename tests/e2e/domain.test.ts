// The domain in the page: a DEM with NODATA cells comes with its default domain,
// triangles outside it are greyed and not measured, the solution is the
// library's within that domain, the link keeps it, and clearing it measures all.
import { readFileSync } from 'node:fs';
import { loadHodt } from 'hodt';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { decodeState } from '../../web/demo/src/share/urlState.ts';
import { hooks, openPage, root, screenshot, settled, startDemo, type Demo } from './harness.ts';

let demo: Demo;
beforeAll(async () => {
  demo = await startDemo();
});
afterAll(async () => {
  await demo?.close();
});

const name = 'dem-utm-inlet-nodata.asc';
const text = readFileSync(`${root}tests/fixtures-gis/${name}`);

describe('the domain', () => {
  test('a NODATA raster is greyed outside its default domain, solved within it, and the link keeps it', async () => {
    const hodt = await loadHodt();
    const read = hodt.readPoints(text, name);
    expect(read.maxEdge).toBeGreaterThan(0);

    const { page, context, errors } = await openPage(demo);
    let h = await hooks(page);
    expect(h.maxEdge).toBeNull();
    expect(h.outsideTriangles).toBe(0);
    await page.selectOption('#objective', 'minmax-edge-normal-angle');
    await settled(page, h.solves);
    h = await hooks(page);
    await page.setInputFiles('#import-file', { name, mimeType: 'text/plain', buffer: text });
    await settled(page, h.solves);
    h = await hooks(page);
    expect(h.notice).toMatch(/NODATA/);
    expect(h.maxEdge).toBe(read.maxEdge);
    expect(Number(await page.locator('#max-edge').inputValue())).toBe(read.maxEdge);
    expect(h.outsideTriangles).toBeGreaterThan(0);

    // The page's solution is the library's within the domain, and differs from
    // the one without it (the hull's slivers across the inlet no longer count).
    using within = hodt.terrain(read.points, { maxEdge: read.maxEdge! });
    using everything = hodt.terrain(read.points);
    const want = within.solve('minmax-edge-normal-angle');
    expect(h.solution!.value).toBe(want.value);
    expect(h.solution!.delaunayValue).toBe(within.delaunayValues()['minmax-edge-normal-angle']);
    expect(within.measures().inside.filter((v) => v === 0).length).toBe(h.outsideTriangles);
    expect(everything.solve('minmax-edge-normal-angle').value).not.toBe(want.value);
    await screenshot(page, 'demo-domain.png');

    // A copied link holds the domain; opening it reproduces the greyed triangles.
    const link = await page.evaluate(() => window.__hodt!.link());
    expect(decodeState(new URL(link!).hash)!.maxEdge).toBe(read.maxEdge);
    const other = await openPage(demo, new URL(link!).hash);
    const copy = await hooks(other.page);
    expect(copy.maxEdge).toBe(read.maxEdge);
    expect(copy.outsideTriangles).toBe(h.outsideTriangles);
    expect({ ...copy.solution, timeMs: 0 }).toEqual({ ...h.solution, timeMs: 0 });

    // Clearing the setting measures every triangle again.
    await page.fill('#max-edge', '');
    await page.locator('#max-edge').dispatchEvent('change');
    await settled(page, h.solves);
    h = await hooks(page);
    expect(h.maxEdge).toBeNull();
    expect(h.outsideTriangles).toBe(0);
    expect(h.solution!.value).toBe(everything.solve('minmax-edge-normal-angle').value);
    expect(errors).toEqual([]);
    expect(other.errors).toEqual([]);
    await other.context.close();
    await context.close();
  });
});
