// Editing in the plan view: add, move, lift and delete points, with undo and redo;
// every edit re-solves.
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { emptySpot, hooks, openPage, screenshot, settled, startDemo, type Demo } from './harness.ts';

let demo: Demo;
beforeAll(async () => {
  demo = await startDemo();
});
afterAll(async () => {
  await demo?.close();
});

describe('editing', () => {
  test('add, move, lift and delete a point; undo and redo restore each state', async () => {
    const { page, context, errors } = await openPage(demo);
    const start = await hooks(page);
    let solves = start.solves;
    const edit = async (action: () => Promise<void>) => {
      await action();
      await settled(page, solves);
      const h = await hooks(page);
      solves = h.solves;
      return h;
    };

    // Add: a click inside the hull adds one point and splits its triangle (2 more).
    const spot = await emptySpot(page);
    const added = await edit(() => page.mouse.click(spot.x, spot.y));
    expect(added.points).toBe(start.points + 1);
    expect(added.triangles).toBe(start.triangles + 2);
    expect(added.selected).toBe(start.points);
    const p = await page.evaluate((i) => window.__hodt!.point(i), start.points);
    const onScreen = await page.evaluate(({ x, y }) => window.__hodt!.planToClient(x, y), p);
    expect(Math.abs(onScreen.x - spot.x)).toBeLessThan(1);
    expect(Math.abs(onScreen.y - spot.y)).toBeLessThan(1);
    expect(added.solution!.objective).toBe(start.objective);

    // Move: drag it 25 px right; the count stays, the position changes.
    let during = start;
    const moved = await edit(async () => {
      await page.mouse.move(spot.x, spot.y);
      await page.mouse.down();
      for (let k = 1; k <= 5; k++) await page.mouse.move(spot.x + 5 * k, spot.y, { steps: 2 });
      await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
      during = await hooks(page);
      await page.mouse.up();
    });
    expect(moved.points).toBe(added.points);
    // The drag preview, edited in place frame by frame (the library's live edits),
    // shows what the terrain built anew from the dropped points has.
    expect(during.points).toBe(moved.points);
    expect(during.triangles).toBe(moved.triangles);
    expect(during.quads).toBe(moved.quads);
    const q = await page.evaluate((i) => window.__hodt!.point(i), start.points);
    expect(q.x).toBeGreaterThan(p.x);
    expect(q.y).toBe(p.y);
    expect(q.z).toBe(p.z);
    await screenshot(page, 'demo-edited.png');

    // Lift: Shift+drag up raises it, x and y stay.
    const at = await page.evaluate(({ x, y }) => window.__hodt!.planToClient(x, y), q);
    const lifted = await edit(async () => {
      await page.keyboard.down('Shift');
      await page.mouse.move(at.x, at.y);
      await page.mouse.down();
      await page.mouse.move(at.x, at.y - 40, { steps: 4 });
      await page.mouse.up();
      await page.keyboard.up('Shift');
    });
    const r = await page.evaluate((i) => window.__hodt!.point(i), start.points);
    expect(lifted.points).toBe(added.points);
    expect([r.x, r.y]).toEqual([q.x, q.y]);
    expect(r.z).toBeGreaterThan(q.z);

    // The z field edits the height exactly.
    const typed = await edit(async () => {
      await page.fill('#point-z', '123.5');
      await page.press('#point-z', 'Enter');
    });
    expect((await page.evaluate((i) => window.__hodt!.point(i), start.points)).z).toBe(123.5);
    expect(typed.points).toBe(added.points);

    // Delete removes the selected point.
    await page.locator('.plan-canvas').focus();
    const deleted = await edit(() => page.keyboard.press('Delete'));
    expect(deleted.points).toBe(start.points);
    expect(deleted.selected).toBeNull();
    expect(deleted.pointsCsv).toBe(start.pointsCsv);

    // Undo walks back through every state; redo forward again.
    const undo = () => edit(() => page.keyboard.press('Control+Z'));
    expect((await undo()).points).toBe(start.points + 1);
    expect((await page.evaluate((i) => window.__hodt!.point(i), start.points)).z).toBe(123.5);
    await undo();
    expect(await page.evaluate((i) => window.__hodt!.point(i), start.points)).toEqual(r);
    await undo();
    expect(await page.evaluate((i) => window.__hodt!.point(i), start.points)).toEqual(q);
    await undo();
    expect(await page.evaluate((i) => window.__hodt!.point(i), start.points)).toEqual(p);
    const original = await edit(() => page.click('#undo'));
    expect(original.points).toBe(start.points);
    expect(original.pointsCsv).toBe(start.pointsCsv);
    expect(original.choice).toBe(start.choice);
    expect(await page.locator('#undo').isDisabled()).toBe(true);

    const again = await edit(() => page.keyboard.press('Control+Shift+Z'));
    expect(again.points).toBe(start.points + 1);
    const redone = await edit(() => page.click('#redo'));
    expect(await page.evaluate((i) => window.__hodt!.point(i), start.points)).toEqual(q);
    expect(redone.points).toBe(start.points + 1);
    expect(errors).toEqual([]);
    await context.close();
  });

  test('a click on a point in the 3D view selects it; Escape deselects', async () => {
    const { page, context, errors } = await openPage(demo);
    // The point nearest the camera (lowest on screen) is never hidden by the terrain.
    const { index, at } = await page.evaluate(() => {
      const h = window.__hodt!;
      let best = { index: 0, at: h.threeToClient(0) };
      for (let i = 1; i < h.points; i++) {
        const at = h.threeToClient(i);
        if (at.y > best.at.y) best = { index: i, at };
      }
      return best;
    });
    // Just above it: on the surface, not on its outline.
    await page.mouse.click(at.x, at.y - 3);
    await page.waitForFunction((i) => window.__hodt!.selected === i, index);
    expect(await page.locator('#selection').textContent()).toContain(`Point ${index}:`);
    await page.keyboard.press('Escape');
    await page.waitForFunction(() => window.__hodt!.selected === null);
    expect(errors).toEqual([]);
    await context.close();
  });
});
