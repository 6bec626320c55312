/// <reference path="../../web/demo/src/globals.d.ts" />
// End to end: serve web/demo with Vite, open it in headless Chromium, check the
// page renders the terrain without console errors, and keep a screenshot in
// test-results/demo.png. Needs the built wasm (web/src/wasm) and /usr/bin/chromium.
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import type { AddressInfo } from 'node:net';
import { fileURLToPath } from 'node:url';
import { chromium, type Browser, type Page } from 'playwright-core';
import { createServer, type ViteDevServer } from 'vite';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { decodePng } from './png.ts';

const root = fileURLToPath(new URL('../../', import.meta.url));
const TIMEOUT = 120_000;

let server: ViteDevServer;
let browser: Browser;
let page: Page;
let url: string;
const errors: string[] = [];

beforeAll(async () => {
  if (!existsSync(`${root}web/src/wasm/hodt.wasm`)) throw new Error('web/src/wasm/hodt.wasm is missing: run `npm run build`');
  server = await createServer({
    configFile: `${root}web/demo/vite.config.ts`,
    logLevel: 'warn',
    clearScreen: false,
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false },
  });
  await server.listen();
  const { port } = server.httpServer!.address() as AddressInfo;
  url = `http://127.0.0.1:${port}/`;

  browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: [
      '--headless',
      '--no-sandbox',
      '--disable-gpu',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--no-first-run',
      '--enable-unsafe-swiftshader', // keep software WebGL available without a GPU
    ],
  });
  page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(String(e)));
}, TIMEOUT);

afterAll(async () => {
  await browser?.close();
  await server?.close();
}, TIMEOUT);

describe('demo page', () => {
  test(
    'renders the volcano terrain with its flippable quads',
    async () => {
      await page.goto(url);
      await page.waitForFunction(() => window.__hodt?.ready === true, undefined, { timeout: 90_000 });
      const info = (await page.evaluate(() => window.__hodt))!;
      expect(info.points).toBeGreaterThan(1000);
      expect(info.triangles).toBeGreaterThan(info.points);
      expect(info.quads).toBeGreaterThan(0);

      expect(await page.locator('h1').textContent()).toContain('first order Delaunay triangulations');
      expect(await page.locator('#count-quads').textContent()).toBe(info.quads.toLocaleString('en'));
      const options = await page.locator('#objective option').count();
      expect(options).toBe(13);

      mkdirSync(`${root}test-results`, { recursive: true });
      const shot = await page.screenshot();
      writeFileSync(`${root}test-results/demo.png`, shot);
      const image = decodePng(shot);
      const colors = new Set<number>();
      const { data } = image;
      for (let i = 0; i < data.length; i += 4) colors.add((data[i]! << 16) | (data[i + 1]! << 8) | data[i + 2]!);
      expect(colors.size).toBeGreaterThan(500);

      // A region of the canvas away from the panel is mostly terrain, not background.
      const varied = countVaried(image, 0.45, 0.55, 0.2, 0.8);
      expect(varied).toBeGreaterThan(0.3);

      expect(errors).toEqual([]);
    },
    TIMEOUT,
  );

  test(
    'Optimize reports the result or the refusal in the status line',
    async () => {
      await page.selectOption('#objective', 'min-local-minima');
      await page.click('#optimize');
      const status = page.locator('#status');
      await expect
        .poll(async () => status.getAttribute('data-kind'), { timeout: 60_000 })
        .toMatch(/^(ok|error)$/);
      expect((await status.textContent())!.length).toBeGreaterThan(10);
      writeFileSync(`${root}test-results/demo-optimize.png`, await page.screenshot());
      expect(await page.evaluate(() => window.__hodt?.ready)).toBe(true);
      expect(errors).toEqual([]);
    },
    TIMEOUT,
  );

  test(
    'a small terrain (?points=20&method=brute-force) is solved and redrawn',
    async () => {
      await page.goto(`${url}?points=20&method=brute-force`);
      await page.waitForFunction(() => window.__hodt?.ready === true, undefined, { timeout: 90_000 });
      const info = (await page.evaluate(() => window.__hodt))!;
      expect(info.quads).toBeGreaterThan(0);
      expect(info.quads).toBeLessThanOrEqual(24);
      await page.selectOption('#objective', 'min-total-edge-length');
      await page.click('#optimize');
      const status = page.locator('#status');
      await expect.poll(async () => status.getAttribute('data-kind'), { timeout: 60_000 }).toBe('ok');
      expect(await status.textContent()).toContain('min-total-edge-length');
      writeFileSync(`${root}test-results/demo-small.png`, await page.screenshot());
      expect(errors).toEqual([]);
    },
    TIMEOUT,
  );
});

/** Fraction of pixels in a box (fractions of width/height) that differ from the
 * median background, i.e. are drawn. */
function countVaried(
  image: ReturnType<typeof decodePng>,
  x0: number,
  x1: number,
  y0: number,
  y1: number,
): number {
  const { width, height, data } = image;
  let drawn = 0;
  let total = 0;
  for (let y = Math.floor(y0 * height); y < y1 * height; y++) {
    for (let x = Math.floor(x0 * width); x < x1 * width; x++) {
      const i = 4 * (y * width + x);
      const r = data[i]!, g = data[i + 1]!, b = data[i + 2]!;
      // The page background is a pale grey-green gradient: near-equal channels.
      if (Math.max(r, g, b) - Math.min(r, g, b) > 24 || Math.max(r, g, b) < 150) drawn++;
      total++;
    }
  }
  return drawn / total;
}
