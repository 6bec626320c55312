import type { HodtTestHooks } from '../globals.d.ts';

/** Publishes the page's state for tests/e2e on window.__hodt. */
export function publishHooks(hooks: HodtTestHooks): void {
  window.__hodt = hooks;
}
