// The small-input table of `npm run bench`: what a student clicking "k + 1" on a
// classroom terrain waits for. Terrains of 60 and 200 points of four kinds
// (random places, DEM-like heights in whole metres, a cocircular grid, a
// jittered grid), every objective at orders 2..8, the native CLI and the wasm
// library side by side; per order and size the slowest case of each, how many
// took longer than the target (a second for 60 points, five for 200) and how
// many were proven optimal.
import { spawnSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { OBJECTIVES, hill, rng, runAlone } from './common.mjs';

// Places in a 100 m square (grids: the largest square of at most n points); heights in metres.
export const SMALL_KINDS = {
  random(n, r) {
    const p = new Float64Array(3 * n);
    for (let i = 0; i < n; ++i) p.set([100 * r(), 100 * r(), 20 * r()], 3 * i);
    return p;
  },
  // Whole-metre heights, as DEMs store them: ties between neighbours.
  dem(n, r) {
    const p = new Float64Array(3 * n);
    for (let i = 0; i < n; ++i) { const x = r(), y = r(); p.set([100 * x, 100 * y, Math.round(30 * hill(x, y))], 3 * i); }
    return p;
  },
  // Every cell cocircular: the most quads and the largest regions.
  grid(n) {
    const w = Math.floor(Math.sqrt(n)), p = new Float64Array(3 * w * w);
    for (let j = 0; j < w; ++j) for (let i = 0; i < w; ++i) p.set([10 * i, 10 * j, Math.round(30 * hill(i / w, j / w))], 3 * (j * w + i));
    return p;
  },
  'jittered grid'(n, r) {
    const w = Math.floor(Math.sqrt(n)), p = new Float64Array(3 * w * w);
    for (let j = 0; j < w; ++j)
      for (let i = 0; i < w; ++i) p.set([10 * i + 4 * (r() - 0.5), 10 * j + 4 * (r() - 0.5), 30 * hill(i / w, j / w)], 3 * (j * w + i));
    return p;
  },
};

export async function runSmallInputs({ root, tmp, hodt, log, quick, sizes = quick ? [60] : [60, 200] }) {
  const orders = quick ? [2, 4, 8] : [2, 3, 4, 5, 6, 7, 8];
  const rows = [];
  for (const n of sizes) {
    const targetMs = n <= 60 ? 1000 : 5000;
    const sets = Object.entries(SMALL_KINDS).map(([kind, make], s) => {
      const xyz = make(n, rng(31 + s));
      const file = join(tmp, `small-${s}-${n}.txt`);
      let text = '';
      for (let i = 0; i < xyz.length; i += 3) text += `${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}\n`;
      writeFileSync(file, text);
      return { kind, file, terrain: hodt.terrain(xyz) };
    });
    log(`\nsmall inputs, ${n} points (${sets.map((s) => s.kind).join(', ')}; ${OBJECTIVES.length} objectives): per order the slowest native and wasm solves, how many took over ${targetMs / 1000} s (native / wasm), and how many were proven optimal`);
    for (const order of orders) {
      const row = { n, order, runs: 0, proven: 0, native: { ms: 0 }, wasm: { ms: 0 }, targetMs, over: { native: 0, wasm: 0 }, errors: [] };
      for (const { kind, file, terrain } of sets)
        for (const objective of OBJECTIVES) {
          const name = `${kind} ${objective}`;
          const t0 = performance.now();
          const r = spawnSync(`${root}/build/native/hodt`, ['solve', file, '--objective', objective, '--order', String(order)], { encoding: 'utf8', maxBuffer: 1 << 26 });
          const nativeMs = performance.now() - t0;
          const t1 = performance.now();
          let wasm = null;
          try {
            wasm = terrain.solve(objective, { order });
          } catch (e) {
            row.errors.push(`${name} (wasm): ${e.message}`);
          }
          const wasmMs = performance.now() - t1;
          ++row.runs;
          row.over.native += nativeMs > targetMs;
          row.over.wasm += wasmMs > targetMs;
          if (r.status !== 0) { row.errors.push(`${name}: ${r.stderr.trim()}`); continue; }
          const native = JSON.parse(r.stdout);
          if (native.optimal && wasm?.optimal) ++row.proven;
          if (wasm && (wasm.value !== native.value || wasm.optimal !== native.optimal)) row.errors.push(`${name}: wasm ${wasm.value} (optimal ${wasm.optimal}), native ${native.value} (optimal ${native.optimal})`);
          if (nativeMs > row.native.ms) row.native = { ms: nativeMs, case: name, optimal: native.optimal };
          if (wasmMs > row.wasm.ms) row.wasm = { ms: wasmMs, case: name, optimal: wasm?.optimal ?? false };
        }
      rows.push(row);
      const slow = (s) => `${s.ms.toFixed(0).padStart(6)} ms (${s.case}${s.optimal ? '' : ', not proven'})`;
      log(`  k=${order}  native ${slow(row.native)}  wasm ${slow(row.wasm)}  over ${targetMs / 1000} s: ${row.over.native} / ${row.over.wasm}  proven ${row.proven}/${row.runs}${row.errors.length ? `  ERRORS: ${row.errors.join('; ')}` : ''}`);
    }
    for (const { terrain } of sets) terrain.dispose();
  }
  return rows;
}

// Alone, after a build: `node bench/small_inputs.mjs [--quick] [--sizes=60]`.
const sizes = process.argv.find((a) => a.startsWith('--sizes='))?.slice(8).split(',').map(Number);
await runAlone(import.meta.url, (context) => runSmallInputs({ ...context, quick: process.argv.includes('--quick'), ...(sizes ? { sizes } : {}) }));
