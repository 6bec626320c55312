// Issue 57, item 2: every step of the first lesson opens a terrain made for it
// (a built-in generator with a seed, reproduced exactly by the page's link), and
// what the step says about it holds: each claim is checked here against the
// library, run in Node on the points the page loaded.
import { OBJECTIVE_IDS, type ObjectiveId } from 'hodt';
import type { Page } from 'playwright-core';
import { describe, expect, test } from 'vitest';
import { decodeState } from '../../web/demo/src/share/urlState.ts';
import { fractalPoints } from '../../web/demo/src/terrains/fractal.ts';
import { jitteredGridPoints } from '../../web/demo/src/terrains/jitteredGrid.ts';
import { uniformPoints } from '../../web/demo/src/terrains/uniform.ts';
import { LESSON_STEPS, type LessonTab } from '../../web/demo/src/teach/lessonSteps.ts';
import { hooks, openPage, setUpDemo, settled } from './harness.ts';

const env = setUpDemo();

const step = (tab: LessonTab) => LESSON_STEPS.find((s) => s.tab === tab)!;
// The generators the steps use (the catalog's volcano needs Vite's aliases).
const MAKE: Record<string, (n: number, seed: number) => Float64Array> = { uniform: uniformPoints, grid: jitteredGridPoints, fractal: fractalPoints };

/** Opens the page, clicks the step's Go, and returns the points the page then holds. */
async function go(tab: LessonTab): Promise<{ page: Page; close: () => Promise<void>; errors: string[]; points: Float64Array }> {
  const { page, context, errors } = await openPage(env.demo);
  const solves = (await hooks(page)).solves;
  await page.click('.segmented button[data-view="teach"]');
  await page.click('#teach-lesson summary');
  await page.click(`#lesson-${tab}`);
  await page.waitForFunction((t) => window.__hodtTeach?.visible && window.__hodtTeach.tab === t, tab);
  const s = step(tab);
  let points: Float64Array = new Float64Array(0);
  if (s.terrain) {
    const expected = MAKE[s.terrain.kind]!(s.terrain.count, s.terrain.seed);
    await page.waitForFunction((n) => window.__hodt!.points === n, expected.length / 3);
    await settled(page, solves);
    const h = await hooks(page);
    if (s.objective) expect(h.objective).toBe(s.objective);
    // The link reproduces the step: its generator and seed, and the exact points.
    const link = decodeState(new URL((await page.evaluate(() => window.__hodt!.link()))!).hash)!;
    expect(link.source).toEqual(s.terrain);
    // (The same generator in Node: Math.exp may differ from the browser's in the last bit.)
    expect(link.points.length).toBe(expected.length);
    link.points.forEach((v, i) => expect(Math.abs(v - expected[i]!)).toBeLessThanOrEqual(1e-12 * Math.max(1, Math.abs(v))));
    // The link holds the exact points the page shows, and those are what the claims are checked on.
    expect(link.points).toEqual(Float64Array.from(csvPoints((await hooks(page)).pointsCsv)));
    if (s.epsilon !== undefined) expect(link.epsilon).toBe(s.epsilon);
    points = link.points;
  }
  return { page, errors, points, close: () => context.close() };
}

const index = (id: ObjectiveId) => OBJECTIVE_IDS.indexOf(id);

function csvPoints(csv: string): number[] {
  return csv.trim().split('\n').filter((l) => /^[-\d]/.test(l)).flatMap((l) => l.split(',').map(Number));
}

describe('the first lesson', () => {
  test('step 1: Delaunay is not optimal, and the best triangulation changes with the objective', async () => {
    const { page, errors, points, close } = await go('brute');
    using terrain = env.hodt.terrain(points);
    const m = terrain.numQuads;
    expect(m).toBeLessThanOrEqual(10);
    const all = terrain.enumerateAll();
    const objectives: ObjectiveId[] = ['min-mixed-vertices', 'min-local-minima'];
    const best = objectives.map((o) => Math.min(...Array.from({ length: 1 << m }, (_, c) => all[13 * c + index(o)]!)));
    const optimal = objectives.map((o, i) => new Set(Array.from({ length: 1 << m }, (_, c) => c).filter((c) => all[13 * c + index(o)] === best[i])));
    objectives.forEach((o, i) => expect(all[index(o)], o).toBeGreaterThan(best[i]!)); // choice 0 is Delaunay
    expect([...optimal[0]!].filter((c) => optimal[1]!.has(c))).toEqual([]);
    // The view shows these: its best card is the library's optimum.
    await page.waitForFunction(() => (window.__hodtTeach!.view('brute')!.count as number) > 0);
    const v = (await page.evaluate(() => window.__hodtTeach!.view('brute'))) as { values: number[]; choices: number[] };
    expect(v.values[0]).toBe(best[0]);
    expect(optimal[0]!.has(v.choices[0]!)).toBe(true);
    expect(errors).toEqual([]);
    await close();
  });

  test('step 2: the 2-SAT search answers no by a contradiction and yes by an assignment', async () => {
    const { errors, points, close } = await go('sat');
    using terrain = env.hodt.terrain(points);
    const tests = terrain.explain(step('sat').objective!).search!.tests;
    expect(tests.some((t) => !t.satisfiable && !t.immediateNo && t.conflicts.length > 0)).toBe(true);
    expect(tests.some((t) => t.satisfiable)).toBe(true);
    expect(errors).toEqual([]);
    await close();
  });

  test('step 3: a smaller epsilon gives more layers and shifts and a narrower proven gap', async () => {
    const { page, errors, points, close } = await go('baker');
    using terrain = env.hodt.terrain(points);
    const optimum = terrain.solve('max-convex-edges', { method: 'exact' });
    expect(optimum.optimal).toBe(true);
    const runs = [0.5, 0.25].map((epsilon) => terrain.explain('max-convex-edges', { method: 'approx', epsilon }).baker!);
    const gap = (b: (typeof runs)[number]) => Math.min(...b.shifts.map((s) => s.bound)) - Math.max(...b.shifts.map((s) => s.value));
    expect(runs[1]!.lambda).toBeGreaterThan(runs[0]!.lambda);
    expect(runs[1]!.shifts.length).toBeGreaterThan(runs[0]!.shifts.length);
    expect(gap(runs[1]!)).toBeLessThan(gap(runs[0]!));
    for (const b of runs) for (const s of b.shifts) expect(s.value <= optimum.value && optimum.value <= s.bound).toBe(true);
    // The view is at the step's epsilon.
    await page.waitForFunction(() => window.__hodtTeach!.view('baker')!.lambda !== null, undefined, { timeout: 60_000 });
    expect((await page.evaluate(() => window.__hodtTeach!.view('baker')))!.lambda).toBe(runs[0]!.lambda);
    expect(errors).toEqual([]);
    await close();
  });

  test('step 4: the gadget’s optimum is a constant plus the MAX-2-SAT optimum', async () => {
    const { page, errors, close } = await go('gadget');
    await page.waitForFunction(() => {
      const v = window.__hodtTeach!.view('gadget')!;
      return v.certificate !== null && v.solved;
    }, undefined, { timeout: 90_000 });
    const v = (await page.evaluate(() => window.__hodtTeach!.view('gadget'))) as Record<string, any>;
    expect(v.optimal).toBe(true);
    expect(v.value).toBe(v.certificate.constant + v.optimum);
    expect(errors).toEqual([]);
    await close();
  });

  test('step 5: the fewest pits falls as k grows (k = 1 to 2, and 2 to 3)', async () => {
    const { errors, points, close } = await go('order');
    using terrain = env.hodt.terrain(points);
    const pits = [1, 2, 3].map((order) => terrain.solve('min-local-minima', { order }));
    for (const s of pits) expect(s.optimal).toBe(true);
    expect(pits[1]!.value).toBeLessThan(pits[0]!.value);
    expect(pits[2]!.value).toBeLessThan(pits[1]!.value);
    expect(errors).toEqual([]);
    await close();
  });

  test('step 6: the fewest pits at order 1 and 2 leaves fewer pits, none new, and each removed pit’s whole basin joins one neighbour', async () => {
    const { page, errors, points, close } = await go('water');
    using terrain = env.hodt.terrain(points);
    const delaunay = terrain.drainage();
    const pits = [delaunay.pits.length];
    for (const k of [1, 2]) {
      const solution = terrain.solve('min-local-minima', { order: k });
      expect(solution.optimal).toBe(true);
      const optimum = terrain.drainage(solution.triangles);
      pits.push(optimum.pits.length);
      expect([...optimum.outlets]).toEqual([...delaunay.outlets]);
      // No new pit: the optimum's pits are some of Delaunay's.
      for (const p of optimum.pits) expect(delaunay.pits).toContain(p);
      // Each pit that went: every point of its Delaunay basin ends at one other pit or outlet.
      for (const gone of [...delaunay.pits].filter((p) => !optimum.pits.includes(p))) {
        const ends = new Set<number>();
        delaunay.basin.forEach((b, v) => b === gone && ends.add(optimum.basin[v]!));
        expect(ends.size, `the basin of pit ${gone}`).toBe(1);
        expect(ends.has(gone)).toBe(false);
      }
      // The view shows these, side by side (the step starts it at order 1; then the order select).
      if (k > 1) await page.selectOption('#water-order', String(k));
      await page.waitForFunction((o) => {
        const v = window.__hodtTeach!.view('water')!;
        return v.order === o && v.optimum !== null;
      }, k);
      const v = (await page.evaluate(() => window.__hodtTeach!.view('water'))) as Record<string, any>;
      expect(v.layout).toBe('both');
      expect(v.objective).toBe('min-local-minima');
      expect(v.delaunay.pits).toBe(delaunay.pits.length);
      expect(v.optimum.pits).toBe(optimum.pits.length);
      expect(v.optimum.basins).toBe(optimum.pits.length + optimum.outlets.length);
    }
    // Fewer than Delaunay at order 1, fewer still at order 2.
    expect(pits[1]!).toBeLessThan(pits[0]!);
    expect(pits[2]!).toBeLessThan(pits[1]!);
    // The step starts the view where its claim is: order 1, both panes, whatever was chosen before.
    await page.selectOption('#water-order', '4');
    await page.click('#water-show-delaunay');
    await page.click('#lesson-water');
    await page.waitForFunction(() => {
      const v = window.__hodtTeach!.view('water')!;
      return v.order === 1 && v.layout === 'both' && v.optimum !== null;
    });
    expect(errors).toEqual([]);
    await close();
  });
});
