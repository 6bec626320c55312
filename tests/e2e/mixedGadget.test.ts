// The Teach tab's Section 3.1 gadget (fewest mixed vertices) in Chromium: for a
// satisfiable and an unsatisfiable 3-SAT formula, what the page says about the
// reduction is checked against the library in Node on the points the page built,
// and formulas the layout cannot take are refused with a message. Screenshots of
// the view at 1440x900 and 1280x720 go to test-results/ (and docs/screenshots/
// with HODT_SCREENSHOTS=1).
import type { Page } from 'playwright-core';
import { describe, expect, test } from 'vitest';
import { buildGadget, keepScreenshots, openPage, screenshot, setUpDemo } from './harness.ts';
import { parseCnf } from '../../web/demo/src/teach/formula.ts';

const env = setUpDemo();

const build = (page: Page, formula: string) => buildGadget(page, 'mixed', formula);

describe('mixed vertices gadget (Section 3.1)', () => {
  for (const [formula, satisfiable, viewport, shot] of [
    ['x | y | z, !x | y, !y | w, !z', true, { width: 1440, height: 900 }, 'teach-mixed.png'],
    ['x | y | z, !x | w | v, !y, !z, !w, !v', false, { width: 1280, height: 720 }, 'teach-mixed-1280.png'],
  ] as const) {
    test(`${satisfiable ? 'satisfiable' : 'unsatisfiable'} "${formula}": the page's claim matches the library`, async () => {
      const { page, context, errors } = await openPage(env.demo, '', viewport);
      await page.click('.segmented button[data-view="teach"]');
      await page.click('#teach-tab-mixed');
      await page.waitForFunction(() => window.__hodtTeach?.visible && window.__hodtTeach.tab === 'mixed');
      const v = await build(page, formula);
      expect(v.error).toBeNull();
      expect(v.satisfiable).toBe(satisfiable);
      // The library in Node, on the page's points: the exact optimum.
      using terrain = env.hodt.terrain(Float64Array.from(v.points as number[]));
      const s = terrain.solve('min-mixed-vertices', { method: 'exact' });
      expect(s.optimal).toBe(true);
      expect(v.value).toBe(s.value);
      // The reduction: the floor exactly when satisfiable, more when not.
      if (satisfiable) expect(s.value).toBe(v.floor);
      else expect(s.value).toBeGreaterThan(v.floor);
      expect(v.wrongAssignments).toBe(0);
      expect(v.holds).toBe(true);
      expect(await page.locator('#mixed-check').getAttribute('data-ok')).toBe('true');
      expect(await page.locator('#mixed-satisfiable').textContent()).toBe(satisfiable ? 'satisfiable' : 'unsatisfiable');
      if (satisfiable) {
        // The values read from the fans satisfy every clause, the three-literal one included.
        const f = parseCnf(formula, 1, 3, 'x');
        const a = v.assignment as boolean[];
        expect(f.clauses.every((c) => c.some((l) => a[l.variable] !== l.negated))).toBe(true);
      }
      await page.waitForTimeout(250);
      await screenshot(page, shot);
      keepScreenshots(shot);
      expect(errors).toEqual([]);
      await context.close();
    });
  }

  test('formulas the layout cannot take are refused with a message, not a wrong claim', async () => {
    const { page, context, errors } = await openPage(env.demo);
    await page.click('.segmented button[data-view="teach"]');
    await page.click('#teach-tab-mixed');
    const v = await build(page, 'x | y, x | !y');
    expect(v.error).toMatch(/turn both ways/);
    expect(v.holds).toBeNull();
    expect(await page.locator('#mixed-summary').textContent()).toMatch(/^Cannot build the gadget: /);
    expect(await page.locator('#mixed-check').count()).toBe(0);
    const same = await build(page, 'x | y | z, !x | y | !z');
    expect(same.error).toMatch(/same three variables/);
    const four = await build(page, 'w | x | y | z');
    expect(four.error).toMatch(/one to three literals/);
    expect(errors).toEqual([]);
    await context.close();
  });
});
