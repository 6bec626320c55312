// The page loads without console errors and draws both views; screenshots of the
// main states go to test-results/ (and the two best to docs/screenshots/ with
// HODT_SCREENSHOTS=1).
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { keepScreenshots, openPage, screenshot, settled, startDemo, type Demo } from './harness.ts';
import { decodePng, type Image } from './png.ts';

let demo: Demo;
beforeAll(async () => {
  demo = await startDemo();
});
afterAll(async () => {
  await demo?.close();
});

describe('the demo page', () => {
  test('loads without console errors and draws the 3D and plan views', async () => {
    const { page, context, errors } = await openPage(demo);
    expect(await page.locator('h1').textContent()).toContain('first order Delaunay triangulations');
    expect(await page.locator('#objective option').count()).toBe(13);
    const h = await page.evaluate(() => window.__hodt!);
    expect(h.points).toBeGreaterThan(150);
    expect(h.quads).toBeGreaterThan(0);
    expect(h.triangles).toBeGreaterThan(h.points);
    expect(await page.locator('#count-quads').textContent()).toBe(String(h.quads));
    expect(await page.locator('#measures tbody tr').count()).toBe(13);
    expect(await page.locator('#result-value').getAttribute('data-value')).toBe(String(h.solution!.value));

    const image = decodePng(await screenshot(page, 'demo-split.png'));
    for (const id of ['#view-3d', '#view-plan']) {
      const box = (await page.locator(id).boundingBox())!;
      expect(colourfulFraction(image, box), id).toBeGreaterThan(0.08);
      expect(distinctColours(image, box), id).toBeGreaterThan(200);
    }
    expect(errors).toEqual([]);
    await context.close();
  });

  test('3D only and plan only views fill the stage (screenshots)', async () => {
    const { page, context, errors } = await openPage(demo, '', { width: 1200, height: 760 });
    await page.locator('#intro summary').click(); // fold the intro: show the result and the measures
    await page.selectOption('#objective', 'max-convex-edges');
    await settled(page, 1);
    await page.click('.segmented button[data-view="3d"]');
    await page.waitForTimeout(400);
    const three = decodePng(await screenshot(page, 'demo-3d.png'));
    const box3d = (await page.locator('#view-3d').boundingBox())!;
    expect(box3d.width).toBeGreaterThan(800);
    expect(colourfulFraction(three, box3d)).toBeGreaterThan(0.2);

    await page.selectOption('#objective', 'min-mixed-vertices');
    await settled(page, 2);
    await page.click('.segmented button[data-view="plan"]');
    await page.waitForTimeout(300);
    // Hover a point: its class shows next to the cursor.
    const spot = await page.evaluate(() => {
      const h = window.__hodt!;
      const p = h.point(Math.floor(h.points / 2));
      return h.planToClient(p.x, p.y);
    });
    await page.mouse.move(spot.x, spot.y);
    await page.waitForTimeout(200);
    expect(await page.locator('.plan-tip').textContent()).toMatch(/^Point \d+: (convex|concave|flat|mixed|on the boundary)/);
    const plan = decodePng(await screenshot(page, 'demo-plan.png'));
    const boxPlan = (await page.locator('#view-plan').boundingBox())!;
    expect(await page.locator('#view-3d').isVisible()).toBe(false);
    expect(colourfulFraction(plan, boxPlan)).toBeGreaterThan(0.08);
    keepScreenshots('demo-3d.png', 'demo-plan.png');
    expect(errors).toEqual([]);
    await context.close();
  });
});

/** Fraction of the pixels in a box that are clearly coloured (not grey or white). */
function colourfulFraction(image: Image, box: { x: number; y: number; width: number; height: number }): number {
  let coloured = 0;
  let total = 0;
  forPixels(image, box, (r, g, b) => {
    total++;
    if (Math.max(r, g, b) - Math.min(r, g, b) > 30) coloured++;
  });
  return coloured / total;
}

function distinctColours(image: Image, box: { x: number; y: number; width: number; height: number }): number {
  const set = new Set<number>();
  forPixels(image, box, (r, g, b) => set.add((r << 16) | (g << 8) | b));
  return set.size;
}

function forPixels(image: Image, box: { x: number; y: number; width: number; height: number }, f: (r: number, g: number, b: number) => void): void {
  const { width, data } = image;
  for (let y = Math.ceil(box.y); y < Math.floor(box.y + box.height); y += 2) {
    for (let x = Math.ceil(box.x); x < Math.floor(box.x + box.width); x += 2) {
      const i = 4 * (y * width + x);
      f(data[i]!, data[i + 1]!, data[i + 2]!);
    }
  }
}
