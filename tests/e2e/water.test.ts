// The Water view (issue 60 item 3): the drainage of Delaunay and of the optimum
// on the page's terrain, checked against the library run in Node on the very
// points the page shows, and drawn.
import type { Page } from 'playwright-core';
import { expect, test } from 'vitest';
import { encodeState } from '../../web/demo/src/share/urlState.ts';
import { jitteredGridPoints } from '../../web/demo/src/terrains/jitteredGrid.ts';
import { keepScreenshots, openPage, pagePoints, screenshot, setUpDemo } from './harness.ts';

const env = setUpDemo();

const water = (page: Page) => page.evaluate(() => window.__hodtTeach!.view('water')) as Promise<Record<string, any>>;

/** Pixels of the view's canvas that are not blank. */
const paintedPixels = (page: Page) =>
  page.evaluate(() => {
    const canvas = document.querySelector<HTMLCanvasElement>('#teach-water canvas')!;
    const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
    let painted = 0;
    for (let i = 3; i < data.length; i += 4) if (data[i]! > 0) painted++;
    return { painted, total: canvas.width * canvas.height, image: canvas.toDataURL() };
  });

async function solvedAt(page: Page, order: number): Promise<Record<string, any>> {
  await page.waitForFunction((k) => {
    const v = window.__hodtTeach!.view('water')!;
    return v.order === k && (v.optimum !== null || v.failure !== null);
  }, order);
  // The canvas draws on the next animation frame.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return water(page);
}

test('water: the pits and basins of Delaunay and of the optimum are the library’s, toggled and drawn', async () => {
  const { demo, hodt } = env;
  // A terrain whose optimum at order 2 removes pits (checked below with the library).
  const hash = encodeState({ points: jitteredGridPoints(200, 21), objective: 'max-convex-edges', method: 'auto', epsilon: 0.25, order: 1, maxEdge: null, view: 'teach', source: null, exaggeration: null });
  const { page, context, errors } = await openPage(demo, hash);
  await page.click('#teach-tab-water');
  await page.waitForFunction(() => window.__hodtTeach?.visible && window.__hodtTeach.tab === 'water');
  const points = await pagePoints(page);
  using terrain = hodt.terrain(points);
  const delaunay = terrain.drainage();

  const order2 = terrain.drainage(terrain.solve('min-local-minima', { order: 2 }).triangles);
  expect(order2.pits.length).toBeLessThan(delaunay.pits.length);
  for (const k of [1, 2]) {
    if (k > 1) await page.selectOption('#water-order', String(k));
    const v = await solvedAt(page, k);
    expect(v.objective).toBe('min-local-minima');
    expect(v.failure).toBeNull();
    const solution = terrain.solve('min-local-minima', k > 1 ? { order: k } : {});
    const optimum = terrain.drainage(solution.triangles);
    expect(v.delaunay).toEqual({ pits: delaunay.pits.length, outlets: delaunay.outlets.length, basins: delaunay.pits.length + delaunay.outlets.length, segments: points.length / 3 - delaunay.pits.length - delaunay.outlets.length });
    expect(v.optimum.pits).toBe(optimum.pits.length);
    expect(v.optimum.basins).toBe(optimum.pits.length + optimum.outlets.length);
    expect(v.optimum.pits).toBeLessThanOrEqual(v.delaunay.pits);
    const text = await page.locator('#water-counts').textContent();
    expect(text).toMatch(new RegExp(`^Delaunay: ${v.delaunay.pits} pits?, ${v.delaunay.basins} basins?; optimum \\(order ${k}\\): ${v.optimum.pits} pits?, ${v.optimum.basins} basins?$`));
  }

  expect((await water(page)).shown).toBe('optimum');
  const optimumImage = await paintedPixels(page);
  expect(optimumImage.painted).toBeGreaterThan(optimumImage.total / 4);
  await screenshot(page, 'teach-water.png');
  await page.click('#water-show-delaunay');
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  expect((await water(page)).shown).toBe('delaunay');
  expect(await page.locator('#water-show-delaunay').getAttribute('aria-pressed')).toBe('true');
  expect(await page.locator('#teach-water-caption').textContent()).toBe('Drainage of Delaunay');
  const delaunayImage = await paintedPixels(page);
  expect(delaunayImage.painted).toBeGreaterThan(delaunayImage.total / 4);
  // The order 2 optimum has fewer pits, so the two pictures differ.
  expect(delaunayImage.image).not.toBe(optimumImage.image);
  await screenshot(page, 'teach-water-delaunay.png');
  keepScreenshots('teach-water.png', 'teach-water-delaunay.png');
  expect(errors).toEqual([]);
  await context.close();
});
