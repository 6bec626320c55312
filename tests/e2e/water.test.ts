// The Water view (issue 60 item 3): the drainage of Delaunay and of the optimum
// on the page's terrain, side by side, checked against the library run in Node on
// the very points the page shows, and drawn; either alone, for narrow screens.
import type { Page } from 'playwright-core';
import { expect, test } from 'vitest';
import { encodeState } from '../../web/demo/src/share/urlState.ts';
import { jitteredGridPoints } from '../../web/demo/src/terrains/jitteredGrid.ts';
import { keepScreenshots, openPage, pagePoints, screenshot, setUpDemo } from './harness.ts';

const env = setUpDemo();

const water = (page: Page) => page.evaluate(() => window.__hodtTeach!.view('water')) as Promise<Record<string, any>>;
const frames = (page: Page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

/** Pixels of a pane's canvas that are not blank (0 for a hidden pane), and its picture. */
const painted = (page: Page, side: 'delaunay' | 'optimum') =>
  page.evaluate((s) => {
    const pane = document.querySelector<HTMLElement>(`#water-pane-${s}`)!;
    const canvas = pane.querySelector('canvas')!;
    if (pane.hidden) return { visible: false, painted: 0, total: 0, width: 0, image: '' };
    const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
    let n = 0;
    for (let i = 3; i < data.length; i += 4) if (data[i]! > 0) n++;
    return { visible: true, painted: n, total: canvas.width * canvas.height, width: canvas.getBoundingClientRect().width, image: canvas.toDataURL() };
  }, side);

async function solvedAt(page: Page, order: number): Promise<Record<string, any>> {
  await page.waitForFunction((k) => {
    const v = window.__hodtTeach!.view('water')!;
    return v.order === k && (v.optimum !== null || v.failure !== null);
  }, order);
  await frames(page); // the canvases draw on the next animation frame
  return water(page);
}

const words = (pits: number, basins: number) => `${pits} pit${pits === 1 ? '' : 's'}, ${basins} basin${basins === 1 ? '' : 's'}`;

test('water: Delaunay and the optimum side by side, their pits and basins the library’s, in the same colours; either alone', async () => {
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
  const images: Record<string, string> = {};
  for (const k of [1, 2]) {
    if (k > 1) await page.selectOption('#water-order', String(k));
    const v = await solvedAt(page, k);
    expect(v.layout).toBe('both');
    expect(v.objective).toBe('min-local-minima');
    expect(v.failure).toBeNull();
    const solution = terrain.solve('min-local-minima', k > 1 ? { order: k } : {});
    const optimum = terrain.drainage(solution.triangles);
    const counts = { delaunay: [delaunay.pits.length, delaunay.pits.length + delaunay.outlets.length], optimum: [optimum.pits.length, optimum.pits.length + optimum.outlets.length] };
    expect(v.delaunay).toEqual({ pits: delaunay.pits.length, outlets: delaunay.outlets.length, basins: counts.delaunay[1], segments: points.length / 3 - delaunay.pits.length - delaunay.outlets.length });
    expect([v.optimum.pits, v.optimum.basins]).toEqual(counts.optimum);
    // Each pane is captioned with its triangulation and shows the library's counts.
    expect(await page.locator('#water-delaunay-caption').textContent()).toBe(`Delaunay ${words(...(counts.delaunay as [number, number]))}`);
    expect(await page.locator('#water-optimum-caption').textContent()).toBe(`Optimum (order ${k}) ${words(...(counts.optimum as [number, number]))}`);
    expect(await page.locator('#water-pane-optimum canvas').getAttribute('aria-label')).toBe(`Drainage of the optimal triangulation (fewest pits, order ${k})`);
    expect(await page.locator('#water-counts').textContent()).toBe(`Delaunay: ${words(...(counts.delaunay as [number, number]))}; optimum (order ${k}): ${words(...(counts.optimum as [number, number]))}`);
    // Both panes painted, side by side.
    const [left, right] = [await painted(page, 'delaunay'), await painted(page, 'optimum')];
    for (const p of [left, right]) {
      expect(p.visible).toBe(true);
      expect(p.painted).toBeGreaterThan(p.total / 4);
    }
    const [l, r] = await Promise.all(['delaunay', 'optimum'].map((s) => page.locator(`#water-pane-${s}`).boundingBox()));
    expect(r!.x).toBeGreaterThanOrEqual(l!.x + l!.width - 1);
    expect(Math.abs(r!.y - l!.y)).toBeLessThan(1);
    images[`delaunay${k}`] = left.image;
    images[`optimum${k}`] = right.image;
  }
  // Order 2 removed pits: the optimum's picture differs from Delaunay's, which stays.
  expect(images.optimum2).not.toBe(images.delaunay2);
  expect(images.delaunay2).toBe(images.delaunay1);
  await screenshot(page, 'teach-water.png');

  // Either alone, over the whole area.
  for (const side of ['delaunay', 'optimum'] as const) {
    await page.click(`#water-show-${side}`);
    await frames(page);
    expect((await water(page)).layout).toBe(side);
    expect(await page.locator(`#water-show-${side}`).getAttribute('aria-pressed')).toBe('true');
    expect(await page.locator('#water-show-both').getAttribute('aria-pressed')).toBe('false');
    const other = side === 'delaunay' ? 'optimum' : 'delaunay';
    expect((await painted(page, other)).visible).toBe(false);
    const alone = await painted(page, side);
    expect(alone.painted).toBeGreaterThan(alone.total / 4);
    const both = (await page.locator('#teach-water .water-panes').boundingBox())!;
    expect(alone.width).toBeCloseTo(both.width, 0);
    await screenshot(page, `teach-water-${side}.png`);
  }
  await page.click('#water-show-both');
  await frames(page);
  expect((await painted(page, 'delaunay')).visible && (await painted(page, 'optimum')).visible).toBe(true);
  keepScreenshots('teach-water.png', 'teach-water-delaunay.png', 'teach-water-optimum.png');
  expect(errors).toEqual([]);
  await context.close();
});
