// Issue 57, item 1: an order-k region whose count the library did not finish is
// a region with a choice ("at least N", N >= 2), and the sidebar and the Teach
// view count the regions the same way and say so in the same words.
import { expect, test } from 'vitest';
import { encodeState } from '../../web/demo/src/share/urlState.ts';
import { jitteredGridPoints } from '../../web/demo/src/terrains/jitteredGrid.ts';
import { hooks, openPage, setUpDemo } from './harness.ts';

const env = setUpDemo();

test('an unfinished region at k = 8 is a region with a choice, counted alike in the sidebar and the Teach view', async () => {
  // The 2-SAT example grid: at k = 8 most of it is one region too large to enumerate.
  const points = jitteredGridPoints(64, 15);
  using terrain = env.hodt.terrain(points);
  const r = terrain.explain('min-local-minima', { order: 8 }).regions!;
  const unfinished = [...r.complete.keys()].filter((g) => !r.complete[g]);
  expect(unfinished.length).toBeGreaterThan(0);
  for (const g of unfinished) expect(r.triangulations[g]).toBeGreaterThanOrEqual(2);
  const withChoice = Array.from(r.triangulations).filter((c, g) => c >= 2 || !r.complete[g]).length;

  const hash = encodeState({ points, objective: 'min-local-minima', method: 'auto', epsilon: 0.25, order: 8, maxEdge: null, view: 'teach', source: null, exaggeration: null });
  const { page, context, errors } = await openPage(env.demo, hash);
  const sidebar = (await page.locator('#result-regions').textContent())!;
  expect(sidebar).toContain(`${withChoice} region${withChoice === 1 ? '' : 's'} with a choice`);
  expect(sidebar).toContain('at least');
  // The solver's own summary (another count) is not shown beside it.
  expect(await page.locator('#result').textContent()).not.toMatch(/triangulations each/);

  await page.click('#teach-tab-order');
  for (let k = 1; k < 8; k++) await page.click('#order-next');
  await page.waitForFunction(() => {
    const v = window.__hodtTeach!.view('order')!;
    return v.order === 8 && (v.value !== null || v.failure !== null);
  }, undefined, { timeout: 60_000 });
  const v = (await page.evaluate(() => window.__hodtTeach!.view('order'))) as Record<string, any>;
  expect(v.failure).toBeNull();
  expect(v.withChoice).toBe(withChoice);
  expect(v.withChoice).toBeGreaterThan(0);
  // The same words: the caption is the sidebar's line (without its full stop).
  expect(`Order 8: ${sidebar.replace(/\.$/, '')}`).toBe(v.caption);
  expect((await hooks(page)).order).toBe(8);
  expect(errors).toEqual([]);
  await context.close();
});
