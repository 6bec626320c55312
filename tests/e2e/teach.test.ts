// The order control (issue 8) and the teaching views (issue 9), driven to their
// end on fixed instances and checked against the library run in Node on the very
// points the page shows. Screenshots of each view go to test-results/ (and to
// docs/screenshots/ with HODT_SCREENSHOTS=1).
import { loadHodt, type Hodt, type ObjectiveId } from 'hodt';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { decodeState } from '../../web/demo/src/share/urlState.ts';
import { LESSON_STEPS } from '../../web/demo/src/teach/lessonSteps.ts';
import { fractalPoints } from '../../web/demo/src/terrains/fractal.ts';
import { hooks, keepScreenshots, openPage, pagePoints, screenshot, settled, startDemo, type Demo } from './harness.ts';

let demo: Demo;
let hodt: Hodt;
beforeAll(async () => {
  demo = await startDemo();
  hodt = await loadHodt();
});
afterAll(async () => {
  await demo?.close();
});

async function teachView(page: Page, id: string) {
  return page.evaluate((v) => window.__hodtTeach!.view(v), id) as Promise<Record<string, any>>;
}

async function openTeach(page: Page, tab: string): Promise<void> {
  await page.click('.segmented button[data-view="teach"]');
  await page.click(`#teach-tab-${tab}`);
  await page.waitForFunction((t) => window.__hodtTeach?.visible && window.__hodtTeach.tab === t, tab);
}

const keep = (name: string) => keepScreenshots(name);

describe('order control', () => {
  test('order 2 changes the value to the library’s, goes into the link, and draws the useful edges', async () => {
    const { page, context, errors } = await openPage(demo);
    let h = await hooks(page);
    await page.selectOption('#objective', 'max-convex-edges');
    await settled(page, h.solves);
    h = await hooks(page);
    const first = h.solution!.value as number;
    const points = await pagePoints(page);
    using terrain = hodt.terrain(points);
    expect(first).toBe(terrain.solve('max-convex-edges').value);

    await page.selectOption('#order', '2');
    await settled(page, h.solves);
    h = await hooks(page);
    expect(h.order).toBe(2);
    const second = terrain.solve('max-convex-edges', { order: 2 });
    expect(h.solution!.value).toBe(second.value);
    expect(second.value).not.toBe(first);
    expect(await page.locator('#method').isDisabled()).toBe(true);
    expect(await page.locator('#result').textContent()).toContain('order 2');
    expect(decodeState(new URL((await page.evaluate(() => window.__hodt!.link()))!).hash)!.order).toBe(2);

    await page.check('#show-useful');
    await page.waitForFunction(() => window.__hodt!.usefulEdges !== null);
    h = await hooks(page);
    expect(h.usefulEdges).toBe(terrain.usefulEdges(2).length / 2);
    expect(await page.locator('#useful-count').textContent()).toContain(h.usefulEdges!.toLocaleString('en'));
    await page.click('.segmented button[data-view="plan"]');
    await page.waitForTimeout(300);
    await screenshot(page, 'demo-order.png');
    keep('demo-order.png');

    // Back to first order: the first value again, fewer useful edges.
    await page.selectOption('#order', '1');
    await settled(page, h.solves);
    h = await hooks(page);
    expect(h.solution!.value).toBe(first);
    expect(h.usefulEdges).toBe(terrain.usefulEdges(1).length / 2);
    expect(errors).toEqual([]);
    await context.close();
  });
});

describe('teaching views', () => {
  test('2-SAT search: stepping to the end shows the library’s optimum', async () => {
    const { page, context, errors } = await openPage(demo);
    await openTeach(page, 'sat');
    const before = (await hooks(page)).solves;
    await page.click('#sat-small');
    await settled(page, before);
    await page.selectOption('#sat-objective', 'minmax-edge-area-ratio');
    const points = await pagePoints(page);
    using terrain = hodt.terrain(points);
    const expected = terrain.solve('minmax-edge-area-ratio', { trace: true });
    let v = await teachView(page, 'sat');
    expect(v.steps).toBe(expected.trace.length);
    expect(v.steps).toBeGreaterThan(1);
    // Step to a step with clauses, screenshot, then to the end.
    const withClauses = expected.trace.findIndex((t) => t.clauses > t.forced && !t.immediateNo);
    for (let i = 0; i <= Math.max(0, withClauses); i++) await page.click('#sat-next');
    await page.waitForTimeout(250);
    await screenshot(page, 'teach-2sat-step.png');
    keep('teach-2sat-step.png');
    while (!(await teachView(page, 'sat')).atEnd) await page.click('#sat-next');
    v = await teachView(page, 'sat');
    // The view's tests are the library's, clause for clause.
    const explained = terrain.explain('minmax-edge-area-ratio').search!;
    expect(v.tests).toEqual(explained.tests.map((t) => ({ threshold: t.threshold, satisfiable: t.satisfiable, clauses: t.clauses.length / 2, conflicts: t.conflicts.length })));
    expect(explained.tests.some((t) => t.conflicts.length > 0 || t.clauses.length > 2 * t.forced.length)).toBe(true);
    expect(Number(await page.locator('#sat-final').getAttribute('data-value'))).toBe(expected.value);
    // The last satisfiable threshold tested is the optimum.
    const lastYes = [...expected.trace].reverse().find((t) => t.satisfiable);
    if (lastYes) expect(lastYes.threshold).toBe(expected.value);
    expect(await page.locator('#sat-steps li').count()).toBe(expected.trace.length);
    await page.waitForTimeout(250);
    await screenshot(page, 'teach-2sat-final.png');
    expect(errors).toEqual([]);
    await context.close();
  });

  test('Baker layers: every shift, and the smallest bound is the library’s', async () => {
    const { page, context, errors } = await openPage(demo);
    await openTeach(page, 'baker');
    await page.selectOption('#baker-objective', 'max-convex-edges');
    await page.fill('#baker-epsilon', '0.34');
    await page.locator('#baker-epsilon').dispatchEvent('change');
    await page.waitForFunction(() => {
      const v = window.__hodtTeach!.view('baker')!;
      return v.library !== null && (v.shifts as unknown[]).length > 0 && (v.shifts as unknown[]).every((x) => x !== null);
    });
    const points = await pagePoints(page);
    using terrain = hodt.terrain(points);
    const expected = terrain.solve('max-convex-edges', { method: 'approx', epsilon: 0.34 });
    const v = await teachView(page, 'baker');
    expect(v.lambda).toBe(3);
    expect(v.library.value).toBe(expected.value);
    expect(v.library.bound).toBe(expected.bound);
    const shifts = v.shifts as { value: number; bound: number }[];
    expect(shifts).toHaveLength(3);
    const baker = terrain.explain('max-convex-edges', { method: 'approx', epsilon: 0.34 }).baker!;
    expect(v.shifts).toEqual(baker.shifts.map((x) => ({ shift: x.shift, cut: x.dropped, relaxed: x.relaxed, value: x.value, bound: x.bound })));
    expect(Math.min(...shifts.map((s) => s.bound))).toBe(expected.bound ?? expected.value);
    expect(Math.max(...shifts.map((s) => s.value))).toBeLessThanOrEqual(expected.value);
    await page.click('#baker-next');
    await page.click('#baker-next');
    await page.waitForTimeout(250);
    await screenshot(page, 'teach-baker.png');
    keep('teach-baker.png');
    while (!(await teachView(page, 'baker')).atEnd) await page.click('#baker-next');
    expect(await page.locator('#baker-done').count()).toBe(1);

    // Fewest mixed vertices: the shifts' lower bounds, the largest is the library's.
    await page.selectOption('#baker-objective', 'min-mixed-vertices');
    await page.waitForFunction(() => {
      const v = window.__hodtTeach!.view('baker')!;
      return v.objective === 'min-mixed-vertices' && v.library !== null && (v.shifts as unknown[]).length > 0 && (v.shifts as unknown[]).every((x) => x !== null);
    });
    const mixed = terrain.solve('min-mixed-vertices', { method: 'approx', epsilon: 0.34 });
    const w = await teachView(page, 'baker');
    expect(w.library.value).toBe(mixed.value);
    const lower = w.shifts as { value: number; bound: number }[];
    expect(Math.max(...lower.map((s) => s.bound))).toBe(mixed.bound ?? mixed.value);
    expect(Math.min(...lower.map((s) => s.value))).toBeGreaterThanOrEqual(mixed.value);
    expect(errors).toEqual([]);
    await context.close();
  });

  test('hardness gadget: the optimum decodes to an optimal MAX-2-SAT assignment', async () => {
    const { page, context, errors } = await openPage(demo);
    await openTeach(page, 'gadget');
    const formula = 'x1 | x2, !x1 | x2, x1 | !x2, !x1 | !x2, x2 | x3, !x3 | x1, !x2 | !x3';
    await page.fill('#gadget-formula', formula);
    await page.click('#gadget-build');
    await page.waitForFunction(() => window.__hodtTeach!.view('gadget')!.certificate !== null, undefined, { timeout: 60_000 });
    const v = await teachView(page, 'gadget');
    expect(v.error).toBeNull();
    expect(v.optimal).toBe(true);
    // Evaluate the decoded assignment here, and the optimum by brute force here.
    const clauses = v.clauses as { variable: number; negated: boolean }[][];
    const n = (v.variables as string[]).length;
    const satisfied = (a: boolean[]) => clauses.filter((c) => c.some((l) => a[l.variable] !== l.negated)).length;
    let best = 0;
    for (let mask = 0; mask < 1 << n; mask++) best = Math.max(best, satisfied(Array.from({ length: n }, (_, i) => ((mask >> i) & 1) === 1)));
    expect(best).toBe(6); // x1, x2 clauses: 3 of the first 4, then all 3 others
    expect(satisfied(v.assignment as boolean[])).toBe(best);
    expect(v.optimum).toBe(best);
    expect(v.certificate.constant).not.toBeNull();
    expect(v.value).toBe(v.certificate.constant + best);
    expect(await page.locator('#gadget-check').getAttribute('data-ok')).toBe('true');
    await page.waitForTimeout(250);
    await screenshot(page, 'teach-gadget.png');
    keep('teach-gadget.png');
    expect(errors).toEqual([]);
    await context.close();
  });

  test('brute force: all 2^m triangulations, the first one optimal', async () => {
    const { page, context, errors } = await openPage(demo);
    await openTeach(page, 'brute');
    expect((await teachView(page, 'brute')).message).toMatch(/too many/);
    let before = (await hooks(page)).solves;
    await page.click('#brute-small');
    await settled(page, before);
    for (const id of ['minmax-edge-normal-angle', 'min-mixed-vertices', 'max-convex-edges'] as ObjectiveId[]) {
      before = (await hooks(page)).solves;
      await page.selectOption('#objective', id);
      await settled(page, before);
      await page.waitForFunction((n) => window.__hodtTeach!.view('brute')!.drawn === n && window.__hodtTeach!.view('brute')!.objective !== null, 2 ** (await hooks(page)).quads);
      const v = await teachView(page, 'brute');
      expect(v.objective).toBe(id);
      const points = await pagePoints(page);
      using terrain = hodt.terrain(points);
      expect(v.count).toBe(2 ** terrain.numQuads);
      const expected = terrain.solve(id, { method: 'brute-force' }).value;
      expect(v.values[0]).toBe(expected);
      expect(Number(await page.locator('#brute-grid figure').first().getAttribute('data-value'))).toBe(expected);
      expect(await page.locator('#brute-grid figure.optimal').count()).toBe((v.values as number[]).filter((x) => x === expected).length);
    }
    await page.waitForTimeout(200);
    await screenshot(page, 'teach-brute.png');
    keep('teach-brute.png');
    expect(errors).toEqual([]);
    await context.close();
  });

  test('order k: the regions, fixed edges and optimum are the library’s, and regions merge as k grows', async () => {
    const { page, context, errors } = await openPage(demo);
    await openTeach(page, 'order');
    // The view shows the sidebar's objective; choosing another moves the sidebar too.
    expect((await teachView(page, 'order')).objective).toBe((await hooks(page)).objective);
    await page.selectOption('#order-objective', 'min-local-minima');
    await expect.poll(async () => (await hooks(page)).objective).toBe('min-local-minima');
    const at = async (k: number) => {
      await page.waitForFunction((n) => {
        const v = window.__hodtTeach!.view('order')!;
        return v.order === n && v.objective === 'min-local-minima' && (v.value !== null || v.failure !== null);
      }, k, { timeout: 60_000 });
      return teachView(page, 'order');
    };
    const points = await pagePoints(page);
    using terrain = hodt.terrain(points);
    const seen: Record<string, any>[] = [];
    for (const k of [1, 2, 3]) {
      if (k > 1) await page.click('#order-next');
      const v = await at(k);
      expect(v.failure).toBeNull();
      const e = terrain.explain('min-local-minima', { order: k });
      const r = e.regions!;
      expect(v.value).toBe(e.solution.value);
      expect(v.optimal).toBe(e.solution.optimal);
      expect(v.regions).toBe(r.triangulations.length);
      expect(v.withChoice).toBe(Array.from(r.triangulations).filter((c) => c > 1).length);
      expect(v.useful).toBe(r.useful.length / 2);
      expect(v.fixed).toBe(r.fixed.length / 2);
      // The minima drawn are the library's measure of the optimum: their count is its value.
      expect(v.minima).toBe(e.solution.value);
      if (k === 1) expect(v.withChoice).toBe(terrain.numQuads);
      seen.push(v);
    }
    expect(seen[2]!.regions).toBeLessThanOrEqual(seen[0]!.regions);
    expect(seen[2]!.value).toBeLessThanOrEqual(seen[0]!.value);
    await page.waitForTimeout(250);
    await screenshot(page, 'teach-order.png');
    keep('teach-order.png');
    expect(errors).toEqual([]);
    await context.close();
  });

  test('the lesson route opens each tab in order, and every view has a legend', async () => {
    const { page, context, errors } = await openPage(demo);
    await page.click('.segmented button[data-view="teach"]');
    await page.click('#teach-lesson summary');
    const tabs = LESSON_STEPS.map((s) => s.tab);
    expect(tabs).toEqual(['brute', 'sat', 'baker', 'gadget', 'order', 'water']);
    expect(await page.locator('#teach-lesson summary').textContent()).toBe(`A first lesson in ${tabs.length} steps`);
    for (const tab of tabs) {
      await page.click(`#lesson-${tab}`);
      await page.waitForFunction((t) => window.__hodtTeach?.visible && window.__hodtTeach.tab === t, tab);
      expect(await page.locator(`#teach-${tab} .teach-legend li`).count(), tab).toBeGreaterThan(2);
    }
    // The last step loaded its terrain (a fractal relief) into the page.
    const last = LESSON_STEPS.at(-1)!.terrain!;
    expect(last.kind).toBe('fractal');
    await expect.poll(async () => (await hooks(page)).points).toBe(fractalPoints(last.count, last.seed).length / 3);
    await screenshot(page, 'teach-lesson.png');
    expect(errors).toEqual([]);
    await context.close();
  });
});
