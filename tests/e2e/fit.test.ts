// Issue 57, item 5: the page fits. At 1280x720 and 1440x900 the result card is
// on screen without scrolling, the 3D view's label does not cover the terrain and
// no point is clipped, and the buttons' tooltips say what they load. A screenshot
// of every view and Teach tab at both sizes goes to test-results/ (the README's
// come from render.test.ts, teach.test.ts and the gadgets' own tests).
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { LESSON_STEPS } from '../../web/demo/src/teach/lessonSteps.ts';
import { hooks, openPage, screenshot, settled, startDemo, type Demo } from './harness.ts';

let demo: Demo;
beforeAll(async () => {
  demo = await startDemo();
});
afterAll(async () => {
  await demo?.close();
});

const SIZES = [
  { width: 1280, height: 720 },
  { width: 1440, height: 900 },
] as const;

/** Is the element wholly inside the viewport, the page unscrolled? */
async function onScreen(page: Page, selector: string): Promise<boolean> {
  return page.evaluate((s) => {
    const r = document.querySelector(s)!.getBoundingClientRect();
    return window.scrollY === 0 && r.height > 0 && r.top >= 0 && r.bottom <= window.innerHeight && r.left >= 0 && r.right <= window.innerWidth;
  }, selector);
}

describe.each(SIZES)('at $width x $height', (size) => {
  test('the result is on screen, the 3D view shows every point clear of its label', async () => {
    const { page, context, errors } = await openPage(demo, '', size);
    expect(await onScreen(page, '#result')).toBe(true);
    expect(await onScreen(page, '#result-value')).toBe(true);
    const h = await hooks(page);
    await page.waitForTimeout(400); // the camera frames on the next frame
    const fit = async () => page.evaluate(() => {
      const h = window.__hodt!;
      const view = document.querySelector('#view-3d canvas')!.getBoundingClientRect();
      const label = document.querySelector('#view-3d .view-label')?.getBoundingClientRect() ?? null;
      const pts = Array.from({ length: h.points }, (_, i) => h.threeToClient(i));
      const inside = pts.filter((p) => p.x >= view.left && p.x <= view.right && p.y >= view.top && p.y <= view.bottom).length;
      const underLabel = label ? pts.filter((p) => p.x >= label.left && p.x <= label.right && p.y >= label.top && p.y <= label.bottom).length : 0;
      return { inside, underLabel };
    });
    expect(await fit()).toEqual({ inside: h.points, underLabel: 0 });
    // Raise the highest point far above the rest: the view keeps it in sight.
    const top = await page.evaluate(() => {
      const h = window.__hodt!;
      const zs = Array.from({ length: h.points }, (_, i) => h.point(i).z);
      return { i: zs.indexOf(Math.max(...zs)), z: Math.max(...zs) + 2 * (Math.max(...zs) - Math.min(...zs)) };
    });
    await page.evaluate((i) => window.__hodt!.planToClient(window.__hodt!.point(i).x, window.__hodt!.point(i).y), top.i).then((p) => page.mouse.click(p.x, p.y));
    await page.waitForFunction((i) => window.__hodt!.selected === i, top.i);
    await page.fill('#point-z', String(top.z));
    await page.locator('#point-z').dispatchEvent('change');
    await settled(page, h.solves);
    await page.waitForTimeout(400);
    expect(await page.evaluate((i) => window.__hodt!.point(i).z, top.i)).toBe(top.z);
    expect(await fit()).toEqual({ inside: h.points, underLabel: 0 });
    // (Editing the point scrolled the sidebar down to its fields.)
    await page.evaluate(() => (document.querySelector('.sidebar')!.scrollTop = 0));
    await screenshot(page, `demo-split-${size.width}.png`);
    for (const view of ['3d', 'plan'] as const) {
      await page.click(`.segmented button[data-view="${view}"]`);
      await page.waitForTimeout(400);
      expect(await onScreen(page, '#result')).toBe(true);
      await screenshot(page, `demo-${view}-${size.width}.png`);
    }
    expect(errors).toEqual([]);
    await context.close();
  });

  test('every Teach tab, after its lesson step', async () => {
    const { page, context, errors } = await openPage(demo, '', size);
    await page.click('.segmented button[data-view="teach"]');
    for (const tab of LESSON_STEPS.map((s) => s.tab)) {
      const solves = (await hooks(page)).solves;
      await page.click('#teach-lesson summary');
      await page.click(`#lesson-${tab}`);
      await page.click('#teach-lesson summary'); // closed again, for the picture
      await page.waitForFunction((t) => window.__hodtTeach?.tab === t, tab);
      if (tab !== 'gadget') await settled(page, solves);
      await page.waitForTimeout(tab === 'gadget' ? 2500 : 800);
      expect(await onScreen(page, '#result')).toBe(true);
      await screenshot(page, `teach-${tab}-${size.width}.png`);
    }
    // The two gadgets without a lesson step: their own default formula, solved.
    for (const tab of ['degree', 'mixed']) {
      await page.click(`#teach-tab-${tab}`);
      await page.waitForFunction((t) => window.__hodtTeach?.view(t)?.holds != null, tab, { timeout: 60_000 });
      await page.waitForTimeout(400);
      expect(await onScreen(page, '#result')).toBe(true);
      expect(await onScreen(page, `#${tab}-check`)).toBe(true);
      await screenshot(page, `teach-${tab}-default-${size.width}.png`);
    }
    // Every tab fits on one line of the strip.
    expect(await page.evaluate(() => { const n = document.querySelector('.teach-tabs')!; return n.scrollWidth <= n.clientWidth && new Set([...n.querySelectorAll('button')].map((b) => Math.round(b.getBoundingClientRect().top))).size; })).toBe(1);
    expect(errors).toEqual([]);
    await context.close();
  });
});

test('tooltips say what the buttons load', async () => {
  const { page, context, errors } = await openPage(demo);
  await page.click('.segmented button[data-view="teach"]');
  await page.click('#teach-tab-sat');
  const title = (await page.locator('#sat-small').getAttribute('title'))!;
  const said = Number(/(\d+)-point/.exec(title)![1]);
  let solves = (await hooks(page)).solves;
  await page.click('#sat-small');
  await settled(page, solves);
  expect((await hooks(page)).points).toBe(said);
  // The lesson's steps name the points they load.
  await page.click('#teach-lesson summary');
  for (const tab of ['brute', 'baker', 'order', 'water']) {
    const t = (await page.locator(`#lesson-${tab}`).getAttribute('title'))!;
    const n = Number(/with (\d+) points/.exec(t)![1]);
    solves = (await hooks(page)).solves;
    await page.click(`#lesson-${tab}`);
    await settled(page, solves);
    expect((await hooks(page)).points, tab).toBe(n);
  }
  expect(errors).toEqual([]);
  await context.close();
});
