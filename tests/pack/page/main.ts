// The smoke page: the installed package in a bundled page (and a module worker),
// under a Content-Security-Policy without 'unsafe-eval'. Results go to
// window.__smoke for the test to read.
import * as THREE from 'three';
import { CancelledError, InputError, loadHodt, solveInWorker } from 'hodt';
import { setTriangles, terrainGeometry } from 'hodt/three';
import type { SolveReply, SolveRequest } from '../examples/worker.ts';
import { hills } from './randomPoints.ts'; // tests/js/randomPoints.ts, copied here by the test

declare global {
  interface Window {
    __smoke?: Record<string, unknown>;
  }
}

function points(n: number): Float64Array {
  let s = 7;
  const r = () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
  return Float64Array.from({ length: 3 * n }, r);
}

function inWorker(request: SolveRequest): Promise<{ progress: number; last: SolveReply }> {
  const worker = new Worker(new URL('../examples/worker.ts', import.meta.url), { type: 'module' });
  let progress = 0;
  return new Promise((resolve, reject) => {
    worker.onerror = (e) => reject(new Error(`worker: ${e.message}`));
    worker.onmessage = ({ data }: MessageEvent<SolveReply>) => {
      if (data.kind === 'progress') ++progress;
      else {
        worker.terminate();
        resolve({ progress, last: data });
      }
    };
    worker.postMessage(request);
  });
}

async function main() {
  const hodt = await loadHodt();
  const xyz = points(400);
  const terrain = hodt.terrain(xyz);
  const best = terrain.solve('min-local-minima');
  const geometry = terrainGeometry(THREE, terrain.points, terrain.delaunay().triangles);
  setTriangles(geometry, best.triangles);
  let aborted = '';
  try {
    terrain.solve('max-convex-edges', { signal: AbortSignal.abort() });
  } catch (e) {
    aborted = e instanceof CancelledError ? e.name : String(e);
  }
  let inputError = '';
  try {
    hodt.terrain([0, 0, 0, 1, 0, 0, 0, Number.NaN, 0]);
  } catch (e) {
    inputError = e instanceof InputError ? e.name : String(e); // the name survives minification
  }
  const exact = terrain.solve('max-convex-edges', { method: 'exact' });
  terrain.dispose();
  const worker = await inWorker({ points: xyz, objective: 'max-convex-edges' });
  const last = worker.last;
  // solveInWorker: the library's own worker, bundled by Vite from the package;
  // a 30-second solve stopped by a timer while the page waits.
  const library = await solveInWorker(xyz, 'max-convex-edges', { method: 'exact' });
  const longStart = performance.now();
  const long = await solveInWorker(hills(60, 7), 'min-mixed-vertices', { order: 6, signal: AbortSignal.timeout(100) }).then(
    () => 'solved',
    (e: unknown) => (e instanceof CancelledError ? `${e.name} after ${Math.round(performance.now() - longStart)} ms` : String(e)),
  );
  return {
    ok: true,
    quads: best.choice.length,
    triangles: best.triangles.length / 3,
    indexCount: geometry.getIndex()?.count,
    value: best.value,
    delaunayValue: best.delaunayValue,
    optimal: best.optimal,
    aborted,
    inputError,
    exactValue: exact.value,
    solveInWorker: { value: library.value, triangles: library.triangles.length / 3, long },
    worker: last.kind === 'solved' ? { kind: last.kind, value: last.value, triangles: last.triangles.length / 3, progress: worker.progress } : last,
  };
}

main().then(
  (r) => (window.__smoke = r),
  (e: unknown) => (window.__smoke = { ok: false, error: e instanceof Error ? `${e.name}: ${e.message}\n${e.stack}` : String(e) }),
);
