/// <reference path="../../web/demo/src/globals.d.ts" />
// Shared set-up of the browser tests: the demo served by Vite's dev server, and
// Debian's Chromium driven by playwright-core (never a downloaded browser).
import { copyFileSync, existsSync, mkdirSync, writeFileSync } from 'node:fs';
import type { AddressInfo } from 'node:net';
import { fileURLToPath } from 'node:url';
import type { Browser, BrowserContext, Page } from 'playwright-core';
import { loadHodt, type Hodt } from 'hodt';
import { createServer, type ViteDevServer } from 'vite';
import { afterAll, beforeAll } from 'vitest';
// Debian's Chromium, headless, with software WebGL: the same launch as the package tests.
import { launch as launchChromium } from '../pack/chromium.ts';

export { launchChromium };

export const root = fileURLToPath(new URL('../../', import.meta.url));
export const resultsDir = `${root}test-results`;

export interface Demo {
  url: string;
  browser: Browser;
  close(): Promise<void>;
}

/** A file's demo and the library in Node: started before its tests, stopped after. */
export function setUpDemo(): { readonly demo: Demo; readonly hodt: Hodt } {
  const env = {} as { demo: Demo; hodt: Hodt };
  beforeAll(async () => {
    env.demo = await startDemo();
    env.hodt = await loadHodt();
  });
  afterAll(async () => {
    await env.demo?.close();
  });
  return env;
}

export async function startDemo(): Promise<Demo> {
  if (!existsSync(`${root}web/src/wasm/hodt.wasm`)) throw new Error('web/src/wasm/hodt.wasm is missing: run `npm run build`');
  const server: ViteDevServer = await createServer({
    configFile: `${root}web/demo/vite.config.ts`,
    logLevel: 'warn',
    clearScreen: false,
    // No file watching: a concurrent build rewriting the wasm must not reload the page.
    server: { host: '127.0.0.1', port: 0, strictPort: false, hmr: false, watch: null },
  });
  await server.listen();
  const { port } = server.httpServer!.address() as AddressInfo;
  const browser = await launchChromium();
  return {
    url: `http://127.0.0.1:${port}/`,
    browser,
    async close() {
      await browser.close();
      await server.close();
    },
  };
}

/** A page in a fresh context that records console errors and page errors. */
export async function openPage(
  demo: Demo,
  path = '',
  viewport = { width: 1440, height: 900 },
): Promise<{ page: Page; context: BrowserContext; errors: string[] }> {
  const context = await demo.browser.newContext({ viewport, acceptDownloads: true });
  const page = await context.newPage();
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(demo.url + path);
  await settled(page, 0);
  return { page, context, errors };
}

/** Waits until the page is drawn, no solve runs, and at least `after` + 1 solves
 * have finished. */
export async function settled(page: Page, after: number): Promise<void> {
  await page.waitForFunction(
    (n) => window.__hodt?.ready === true && !window.__hodt.solving && window.__hodt.solves > n,
    after,
    { timeout: 60_000 },
  );
}

export async function hooks(page: Page) {
  return (await page.evaluate(() => {
    const h = window.__hodt!;
    return { ...h, pointsCsv: h.pointsCsv() };
  })) as Omit<NonNullable<Window['__hodt']>, 'pointsCsv'> & { pointsCsv: string };
}

/** The page's points, exactly (the CSV export prints doubles round-trip). */
export async function pagePoints(page: Page): Promise<Float64Array> {
  const csv = (await hooks(page)).pointsCsv;
  const rows = csv.trim().split('\n').filter((l) => /^[-\d]/.test(l));
  return Float64Array.from(rows.flatMap((l) => l.split(',').map(Number)));
}

export async function screenshot(page: Page, name: string): Promise<Buffer> {
  mkdirSync(resultsDir, { recursive: true });
  const shot = await page.screenshot();
  writeFileSync(`${resultsDir}/${name}`, shot);
  return shot;
}

/** With HODT_SCREENSHOTS=1: screenshots taken by screenshot() become the docs' ones. */
export function keepScreenshots(...names: string[]): void {
  if (!process.env.HODT_SCREENSHOTS) return;
  mkdirSync(`${root}docs/screenshots`, { recursive: true });
  for (const name of names) copyFileSync(`${resultsDir}/${name}`, `${root}docs/screenshots/${name}`);
}

/** Client coordinates of a spot in the plan view at least `clear` pixels from
 * every point and inside the hull (a grid search over the points' bounding box). */
export async function emptySpot(page: Page, clear = 16): Promise<{ x: number; y: number; dataX: number; dataY: number }> {
  return page.evaluate((clear) => {
    const h = window.__hodt!;
    const pts = Array.from({ length: h.points }, (_, i) => h.point(i));
    const screen = pts.map((p) => h.planToClient(p.x, p.y));
    const xs = pts.map((p) => p.x);
    const ys = pts.map((p) => p.y);
    const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
    let best = { x: 0, y: 0, dataX: 0, dataY: 0, d: -1 };
    for (let i = 2; i < 18; i++) {
      for (let j = 2; j < 18; j++) {
        const dataX = x0 + ((x1 - x0) * i) / 20;
        const dataY = y0 + ((y1 - y0) * j) / 20;
        const s = h.planToClient(dataX, dataY);
        const d = Math.min(...screen.map((p) => Math.hypot(p.x - s.x, p.y - s.y)));
        if (d > best.d) best = { ...s, dataX, dataY, d };
      }
    }
    if (best.d < clear) throw new Error(`no spot ${clear}px clear of every point`);
    return best;
  }, clear);
}

/** Types a formula into a hardness gadget view (`id`: degree or mixed), builds it
 * and waits until it is refused, solved or failed; returns the view's hooks. */
export async function buildGadget(page: Page, id: string, formula: string): Promise<Record<string, any>> {
  await page.fill(`#${id}-formula`, formula);
  await page.click(`#${id}-build`);
  await page.waitForFunction(
    ([v, f]) => {
      const h = window.__hodtTeach!.view(v!)!;
      return h.formula === f && (h.error !== null || h.solved === true || h.failure !== null);
    },
    [id, formula],
    { timeout: 60_000 },
  );
  return page.evaluate((v) => window.__hodtTeach!.view(v)!, id) as Promise<Record<string, any>>;
}
