// Sharing: the link holds the exact points and settings; opening it elsewhere
// gives the identical triangulation and solution. Bad links show a message.
import { deflateSync } from 'fflate';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { toBase64Url } from '../../web/demo/src/share/base64url.ts';
import { decodeState, encodeState } from '../../web/demo/src/share/urlState.ts';
import { uniformPoints } from '../../web/demo/src/terrains/uniform.ts';
import { emptySpot, hooks, openPage, screenshot, settled, startDemo, type Demo } from './harness.ts';

let demo: Demo;
beforeAll(async () => {
  demo = await startDemo();
});
afterAll(async () => {
  await demo?.close();
});

describe('sharing', () => {
  test('a copied link opened in a fresh page gives the identical solution', async () => {
    const { page, context, errors } = await openPage(demo);
    let h = await hooks(page);
    // Make the state unique: another terrain, an edit, another objective and view.
    await page.selectOption('#terrain-kind', 'fractal');
    await settled(page, h.solves);
    h = await hooks(page);
    const spot = await emptySpot(page);
    await page.mouse.click(spot.x, spot.y);
    await settled(page, h.solves);
    h = await hooks(page);
    await page.selectOption('#objective', 'minmax-edge-area-ratio');
    await settled(page, h.solves);
    await page.click('.segmented button[data-view="plan"]');
    await page.click('#copy-link');
    await expect.poll(() => page.locator('#link').inputValue()).toMatch(/#v1=[A-Za-z0-9_-]+$/);
    const link = await page.locator('#link').inputValue();
    const original = await hooks(page);

    const other = await openPage(demo, link.slice(link.indexOf('#')));
    const copy = await hooks(other.page);
    expect(copy.pointsCsv).toBe(original.pointsCsv);
    expect(copy.objective).toBe('minmax-edge-area-ratio');
    expect(copy.choice).toBe(original.choice);
    expect(copy.triangles).toBe(original.triangles);
    expect(copy.exaggeration).toBe(original.exaggeration);
    expect({ ...copy.solution, timeMs: 0 }).toEqual({ ...original.solution, timeMs: 0 });
    expect(await other.page.locator('.stage').getAttribute('data-view')).toBe('plan');
    expect(await other.page.locator('#terrain-kind').inputValue()).toBe('custom');
    await screenshot(other.page, 'demo-link.png');

    // Pasting another link into the same tab loads it (hashchange).
    const solves = (await hooks(other.page)).solves;
    await other.page.selectOption('#terrain-kind', 'uniform');
    await settled(other.page, solves);
    const uniform = await hooks(other.page);
    const hash = new URL((await other.page.evaluate(() => window.__hodt!.link()))!).hash;
    await page.evaluate((h) => (location.hash = h), hash);
    await page.waitForFunction((csv) => window.__hodt!.pointsCsv() === csv && !window.__hodt!.solving, uniform.pointsCsv);
    expect((await hooks(page)).choice).toBe(uniform.choice);
    expect(errors).toEqual([]);
    expect(other.errors).toEqual([]);
    await other.context.close();
    await context.close();
  });

  test('corrupt, foreign and oversized links show a message and the default terrain', async () => {
    for (const [hash, message] of [
      ['#v1=AAAA-not-deflate', /damaged/],
      ['#v1=abc$', /base64url/],
      ['#v9=AAAA', /format v9/],
      ['#hello', /no state/],
      [`#v1=${'A'.repeat(2_000_100)}`, /too long/],
      // A header that decodes to null (it threw a TypeError and blanked the page).
      [nullHeader(), /its header is null, expected an object/],
    ] as const) {
      const { page, context, errors } = await openPage(demo, hash);
      const h = await hooks(page);
      expect(h.notice, hash.slice(0, 20)).toMatch(message);
      expect(h.points).toBeGreaterThan(100);
      expect(await page.locator('#notice').isVisible()).toBe(true);
      if (hash === '#v1=AAAA-not-deflate') await screenshot(page, 'demo-bad-link.png');
      expect(errors).toEqual([]);
      await context.close();
    }
  });
});

describe('settings through a link', () => {
  test('the height exaggeration comes back exactly, also after an edit that changes the relief', async () => {
    const points = uniformPoints(40, 3);
    const hash = encodeState({ points, objective: 'min-local-minima', method: 'auto', epsilon: 0.25, order: 1, maxEdge: null, view: 'split', source: null, exaggeration: 2.7 });
    const { page, context, errors } = await openPage(demo, hash);
    const h = await hooks(page);
    expect(h.exaggeration).toBe(2.7);
    expect(await page.locator('#exaggeration').textContent()).toContain('×2.7');
    // Raise a point: the relief changes, the view keeps its factor, and so does the link.
    await page.evaluate(() => window.__hodt!.planToClient(0, 0)).then((p) => page.mouse.click(p.x, p.y));
    await page.waitForFunction(() => window.__hodt!.selected === 0);
    await page.fill('#point-z', '40');
    await page.locator('#point-z').dispatchEvent('change');
    await settled(page, h.solves);
    expect(await page.evaluate(() => window.__hodt!.point(0).z)).toBe(40);
    const back = decodeState(new URL((await page.evaluate(() => window.__hodt!.link()))!).hash)!;
    expect(back.exaggeration).toBe(2.7);
    expect(back.points[2]).toBe(40);
    const other = await openPage(demo, new URL((await page.evaluate(() => window.__hodt!.link()))!).hash);
    expect((await hooks(other.page)).exaggeration).toBe(2.7);
    expect(await other.page.locator('#exaggeration').textContent()).toContain('×2.7');
    expect(errors).toEqual([]);
    expect(other.errors).toEqual([]);
    await other.context.close();
    await context.close();
  });
});

/** A well-formed link whose JSON header is `null`. */
function nullHeader(): string {
  const json = new TextEncoder().encode('null');
  const raw = new Uint8Array(4 + json.length + 72);
  new DataView(raw.buffer).setUint32(0, json.length, true);
  raw.set(json, 4);
  return `#v1=${toBase64Url(deflateSync(raw))}`;
}
