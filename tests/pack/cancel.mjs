// Copied into the temporary project and run there with plain Node:
// `node cancel.mjs POINTS.f64` (x, y, z doubles). A long solve in a worker,
// given AbortSignal.timeout(100) as a user would; prints one JSON line.
import { readFileSync } from 'node:fs';
import { CancelledError, solveInWorker } from 'hodt';

const bytes = readFileSync(process.argv[2]);
const points = new Float64Array(bytes.buffer, bytes.byteOffset, bytes.length / 8);
const start = performance.now();
let out;
try {
  const best = await solveInWorker(points, 'min-mixed-vertices', { order: 6, signal: AbortSignal.timeout(100) });
  out = { solved: best.value };
} catch (e) {
  out = { cancelled: e instanceof CancelledError, name: e.name, cause: e.cause?.name };
}
console.log(JSON.stringify({ ...out, ms: Math.round(performance.now() - start) }));
