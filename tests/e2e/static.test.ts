// The demo as a static site (npm run build: build/demo, relative paths), served
// from a subfolder of a plain static host, as a teacher would put it on a school
// server: the page renders, solves, and a copied link reproduces the instance.
import { existsSync } from 'node:fs';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { serveStatic } from '../pack/serve.ts';
import { hooks, launchChromium, openPage, root, screenshot, settled, type Demo } from './harness.ts';

let demo: Demo;
beforeAll(async () => {
  const dir = `${root}build/demo`;
  if (!existsSync(`${dir}/index.html`)) throw new Error('build/demo is missing: run `npm run build`');
  const server = await serveStatic(dir, { prefix: '/courses/geometry/hodt/' });
  const browser = await launchChromium();
  demo = {
    url: server.url,
    browser,
    close: async () => {
      await browser.close();
      await server.close();
    },
  };
});
afterAll(async () => {
  await demo?.close();
});

describe('static build', () => {
  test('served from a subfolder: renders, solves, and a copied link reproduces the instance', async () => {
    const { page, context, errors } = await openPage(demo);
    const before = (await hooks(page)).solves;
    await page.selectOption('#objective', 'min-local-minima');
    await settled(page, before);
    const first = await hooks(page);
    expect(first.points).toBeGreaterThan(100);
    expect(first.solution?.value).toBeTypeOf('number');
    await page.click('#copy-link');
    await expect.poll(() => page.locator('#link').inputValue()).toMatch(/#v1=[A-Za-z0-9_-]+$/);
    const link = await page.locator('#link').inputValue();
    expect(link.startsWith(demo.url)).toBe(true);
    const other = await openPage(demo, link.slice(link.indexOf('#')));
    const second = await hooks(other.page);
    expect(second.pointsCsv).toBe(first.pointsCsv);
    expect(second.objective).toBe('min-local-minima');
    expect(second.solution?.value).toBe(first.solution?.value);
    expect(second.choice).toBe(first.choice);
    await screenshot(other.page, 'demo-static.png');
    expect(errors).toEqual([]);
    expect(other.errors).toEqual([]);
    await context.close();
    await other.context.close();
  });
});
