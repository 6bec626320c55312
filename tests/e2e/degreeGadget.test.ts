// The Teach tab's Section 3.2 gadget (lowest maximum degree) in Chromium: for a
// satisfiable and an unsatisfiable formula, what the page says about the reduction
// is checked against the library in Node on the points the page built, and a
// formula the layout cannot take is refused with a message. Screenshots of the
// view at 1280x720 and 1440x900 go to test-results/ (and docs/screenshots/ with
// HODT_SCREENSHOTS=1).
import type { Page } from 'playwright-core';
import { describe, expect, test } from 'vitest';
import { buildGadget, keepScreenshots, openPage, screenshot, setUpDemo } from './harness.ts';

const env = setUpDemo();

const build = (page: Page, formula: string) => buildGadget(page, 'degree', formula);

/** The library in Node, on the page's points: the exact optimum. */
function nodeOptimum(v: Record<string, any>): { value: number; optimal: boolean } {
  using terrain = env.hodt.terrain(Float64Array.from(v.points as number[]), { maxEdge: v.maxEdge as number });
  const s = terrain.solve('minmax-degree', { method: 'exact' });
  return { value: s.value, optimal: s.optimal };
}

describe('max degree gadget (Section 3.2)', () => {
  for (const [formula, satisfiable, viewport, shot] of [
    ['x | y, !y | z, !x', true, { width: 1440, height: 900 }, 'teach-degree.png'],
    ['x | y, !x, !y', false, { width: 1280, height: 720 }, 'teach-degree-1280.png'],
  ] as const) {
    test(`${satisfiable ? 'satisfiable' : 'unsatisfiable'} "${formula}": the page's claim matches the library`, async () => {
      const { page, context, errors } = await openPage(env.demo, '', viewport);
      await page.click('.segmented button[data-view="teach"]');
      await page.click('#teach-tab-degree');
      await page.waitForFunction(() => window.__hodtTeach?.visible && window.__hodtTeach.tab === 'degree');
      const v = await build(page, formula);
      expect(v.error).toBeNull();
      expect(v.satisfiable).toBe(satisfiable);
      const node = nodeOptimum(v);
      expect(node.optimal).toBe(true);
      expect(v.value).toBe(node.value);
      // The reduction: optimum <= d exactly when satisfiable; the page says it holds.
      expect(node.value <= v.bound).toBe(satisfiable);
      expect(v.wrongAssignments).toBe(0);
      expect(v.holds).toBe(true);
      expect(await page.locator('#degree-check').getAttribute('data-ok')).toBe('true');
      expect(await page.locator('#degree-satisfiable').textContent()).toBe(satisfiable ? 'satisfiable' : 'unsatisfiable');
      await page.waitForTimeout(250);
      await screenshot(page, shot);
      keepScreenshots(shot);
      expect(errors).toEqual([]);
      await context.close();
    });
  }

  test('a formula the layout cannot take is refused with a message, not a wrong claim', async () => {
    const { page, context, errors } = await openPage(env.demo);
    await page.click('.segmented button[data-view="teach"]');
    await page.click('#teach-tab-degree');
    const v = await build(page, 'x | y, x | !y');
    expect(v.error).toMatch(/share two variables/);
    expect(v.holds).toBeNull();
    expect(await page.locator('#degree-summary').textContent()).toMatch(/^Cannot build the gadget: /);
    expect(await page.locator('#degree-check').count()).toBe(0);
    const three = await build(page, 'x | y | z');
    expect(three.error).toMatch(/literals/);
    expect(errors).toEqual([]);
    await context.close();
  });
});
