// Bad files: the library's message (naming the line) is shown and the user's
// points stay; a good file replaces them.
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { hooks, openPage, screenshot, settled, startDemo, type Demo } from './harness.ts';

let demo: Demo;
beforeAll(async () => {
  demo = await startDemo();
});
afterAll(async () => {
  await demo?.close();
});

const file = (name: string, text: string) => ({ name, mimeType: 'text/plain', buffer: Buffer.from(text) });

describe('importing files', () => {
  test('a bad CSV shows the error with its line and keeps the points', async () => {
    const { page, context, errors } = await openPage(demo);
    const before = await hooks(page);
    await page.setInputFiles('#import-file', file('broken.csv', 'x,y,z\n0,0,1\n1,0,2\n0,1\n1,1,4\n'));
    await page.waitForFunction(() => window.__hodt!.notice !== null);
    const h = await hooks(page);
    expect(h.notice).toContain('broken.csv');
    expect(h.notice).toMatch(/line 4/);
    expect(h.notice).toMatch(/unchanged/);
    expect(h.pointsCsv).toBe(before.pointsCsv);
    expect(h.solves).toBe(before.solves);
    await screenshot(page, 'demo-bad-file.png');

    // Collinear points parse but are no terrain: refused the same way.
    await page.setInputFiles('#import-file', file('line.csv', '0 0 0\n1 1 1\n2 2 2\n3 3 3\n'));
    await page.waitForFunction(() => /collinear/.test(window.__hodt!.notice ?? ''));
    expect((await hooks(page)).pointsCsv).toBe(before.pointsCsv);

    // A good JSON file replaces the points (undoable); duplicates are dropped with a note.
    await page.setInputFiles('#import-file', file('five.json', '[[0,0,0],[10,0,1],[10,10,2],[0,10,3],[4,6,9],[4,6,1]]'));
    await settled(page, before.solves);
    const good = await hooks(page);
    expect(good.points).toBe(5);
    expect(good.notice).toMatch(/dropped 1 point/);
    await page.click('#undo');
    await settled(page, good.solves);
    expect((await hooks(page)).pointsCsv).toBe(before.pointsCsv);

    // An ESRI ASCII grid through a drop on the page.
    const asc = 'ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n1 2 3\n4 9 6\n7 8 5\n';
    const dropped = (await hooks(page)).solves;
    await page.evaluate((text) => {
      const data = new DataTransfer();
      data.items.add(new File([text], 'grid.asc'));
      window.dispatchEvent(new DragEvent('drop', { dataTransfer: data, cancelable: true }));
    }, asc);
    await settled(page, dropped);
    expect((await hooks(page)).points).toBe(9);
    expect(errors).toEqual([]);
    await context.close();
  });
});
