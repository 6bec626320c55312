// What the benchmark's scripts share: the objectives (the package's own list),
// a seeded generator, smooth hills for DEM-like heights, and running a table
// alone after a build.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

export { OBJECTIVE_IDS as OBJECTIVES } from '../dist/objectives.js';

// A linear congruential generator: the same points on every machine.
export function rng(seed) {
  let s = seed >>> 0;
  return () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
}

// Smooth hills over the unit square, heights about -1.7 to 1.7.
export const hill = (x, y) => Math.sin(3 * x) * Math.cos(2.3 * y) + 0.5 * Math.sin(7.1 * x + 5.3 * y) + 0.2 * Math.cos(13 * x * y);

// When `moduleUrl` is the script node was started with: runs table({ root, tmp,
// hodt, log }) with a fresh temporary folder and the built library.
export async function runAlone(moduleUrl, table) {
  if (!process.argv[1] || moduleUrl !== new URL(`file://${process.argv[1]}`).href) return;
  const { loadHodt } = await import('../dist/index.js');
  const tmp = mkdtempSync(join(tmpdir(), 'hodt-bench-'));
  try {
    await table({ root: fileURLToPath(new URL('..', import.meta.url)), tmp, hodt: await loadHodt(), log: console.log });
  } finally {
    rmSync(tmp, { recursive: true, force: true });
  }
}
