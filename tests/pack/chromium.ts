// Debian's Chromium through playwright-core (never a downloaded browser), with a
// page that records console errors, page errors and CSP violations.
import { type Browser, chromium, type ConsoleMessage, type Page } from 'playwright-core';

export function launch(): Promise<Browser> {
  return chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: [
      '--headless',
      '--no-sandbox',
      '--disable-gpu',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--no-first-run',
      '--enable-unsafe-swiftshader',
    ],
  });
}

export interface WatchedPage {
  page: Page;
  /** Console errors, uncaught exceptions and failed requests (but a favicon), of
   * the page and its workers. */
  errors: string[];
  /** Console warnings (the wasm glue reports failed streaming compiles here). */
  warnings: string[];
  /** securitypolicyviolation events of the page: "directive blocked-uri". */
  violations(): Promise<string[]>;
}

export async function watchedPage(browser: Browser): Promise<WatchedPage> {
  const page = await browser.newPage();
  const errors: string[] = [];
  const warnings: string[] = [];
  const record = (from: string) => (m: ConsoleMessage) => {
    // Failed loads are reported with their URL by the response handler.
    if (m.type() === 'error' && !m.text().startsWith('Failed to load resource')) errors.push(from + m.text());
    if (m.type() === 'warning') warnings.push(from + m.text());
  };
  page.on('console', record(''));
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('response', (r) => {
    if (r.status() >= 400 && !r.url().endsWith('/favicon.ico')) errors.push(`${r.status()} ${r.url()}`);
  });
  page.on('worker', (w) => w.on('console', record('worker: ')));
  await page.addInitScript(() => {
    const w = window as unknown as { __violations: string[] };
    w.__violations = [];
    document.addEventListener('securitypolicyviolation', (e) => w.__violations.push(`${e.violatedDirective} ${e.blockedURI}`));
  });
  return {
    page,
    errors,
    warnings,
    violations: () => page.evaluate(() => (window as unknown as { __violations: string[] }).__violations),
  };
}
