// `npm run bench`: hodt native, hodt wasm (in this Node process) and delaunator on
// the same points, side by side, in one run. Medians of several repetitions.
// `npm run bench -- --json` prints only the JSON summary. `--kinds=uniform,lidar`
// `--sizes=1e5` runs only those point sets (the first table) at those sizes.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import Delaunator from 'delaunator';
import { loadHodt } from '../dist/index.js';
import { loadModule } from '../dist/load.js';
import { measureEditsInChromium } from '../bench/edit_chromium.mjs';
import { runCliEndToEnd } from '../bench/cli_end_to_end.mjs';
import { runOrderK } from '../bench/order_k.mjs';
import { runSmallInputs } from '../bench/small_inputs.mjs';
import { OBJECTIVES as EXACT, hill, rng } from '../bench/common.mjs';
import { runUsersFiles } from '../bench/users_files.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const jsonOnly = process.argv.includes('--json');
const quick = process.argv.includes('--quick');
const argValue = (name) => process.argv.find((a) => a.startsWith(`${name}=`))?.slice(name.length + 1);
const onlyKinds = argValue('--kinds')?.split(',');
const log = (...a) => { if (!jsonOnly) console.log(...a); };
const tmp = mkdtempSync(join(tmpdir(), 'hodt-bench-'));

const PIPELINE_OBJECTIVE = 'minmax-edge-area-ratio';
// Point sets: uniform; DEM-like (smooth hills sampled at random places); a grid
// (every cell cocircular) with DEM heights; and real data's two shapes: a DEM
// raster after reprojection (a grid at a UTM offset, a cell size not round in
// binary: no coordinate is an integer) and LiDAR-like ground points (random
// places quantised to 1 cm at UTM offsets, duplicates dropped).
const KINDS = {
  uniform(n, r) { return Float64Array.from({ length: 3 * n }, r); },
  dem(n, r) {
    const p = new Float64Array(3 * n);
    for (let i = 0; i < n; ++i) { const x = r(), y = r(); p.set([x, y, hill(x, y) + 0.01 * r()], 3 * i); }
    return p;
  },
  grid(n) {
    const w = Math.round(Math.sqrt(n)), p = new Float64Array(3 * w * w);
    for (let j = 0; j < w; ++j) for (let i = 0; i < w; ++i) p.set([i, j, hill(i / w, j / w)], 3 * (j * w + i));
    return p;
  },
  'utm-grid'(n) {
    const w = Math.round(Math.sqrt(n)), p = new Float64Array(3 * w * w);
    for (let j = 0; j < w; ++j)
      for (let i = 0; i < w; ++i) p.set([731012.3456789 + 74.98765 * i, 4100000.25 + 74.98765 * j, 300 + 200 * hill(i / w, j / w)], 3 * (j * w + i));
    return p;
  },
  lidar(n, r) {
    const side = Math.sqrt(n); // metres: a point per square metre
    const seen = new Set(), out = [];
    for (let i = 0; i < n; ++i) {
      const qx = Math.round(r() * side * 100), qy = Math.round(r() * side * 100);
      const key = qx * 1e9 + qy;
      if (seen.has(key)) continue;
      seen.add(key);
      out.push(500000 + qx / 100, 4100000 + qy / 100, Math.round((150 + 40 * hill(qx / (100 * side), qy / (100 * side))) * 100) / 100);
    }
    return Float64Array.from(out);
  },
};
// Real-data kinds: every objective, and each one's time per point against the
// uniform run of the same size.
const REAL = new Set(['utm-grid', 'lidar']);
const uniformPerPoint = {};

// A fresh module per run (its heap size is that run's peak), warmed up on small
// terrains first: V8 compiles wasm in tiers, and the first call of a big function
// would otherwise pay for the optimising compile. Scattered points and a raster
// (whose triangulation and tied searches take paths of their own).
async function warmModule(objectives) {
  const module = await loadModule();
  for (const xyz of [KINDS.dem(3000, rng(99)), KINDS['utm-grid'](3000)]) {
    const t = module.fromPoints(xyz, false);
    for (let r = 0; r < 3; ++r) for (const o of objectives) { try { t.solve(o, 'auto', 0.25, false, 1, undefined); } catch {} }
    t.delete();
  }
  return module;
}

const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
const time = (f) => { const t0 = performance.now(); const r = f(); return [performance.now() - t0, r]; };

// delaunator is JIT-compiled: warm it up (on a size of its own) before timing it,
// as hodt's module is warmed up, so that neither pays for compilation.
{
  const coords = Float64Array.from({ length: 2e5 }, rng(5));
  for (let i = 0; i < 5; ++i) new Delaunator(coords);
}

const summary = { date: new Date().toISOString(), machine: `${process.platform} ${process.arch}, node ${process.version}`, runs: [] };
const sizes = argValue('--sizes')?.split(',').map(Number) ?? (quick ? [1e3, 1e4] : [1e3, 1e4, 1e5, 1e6]);

for (const kind of Object.keys(KINDS).filter((k) => !onlyKinds || onlyKinds.includes(k))) {
  for (const n of sizes) {
    const reps = n >= 1e5 ? 3 : 5;
    const xyz = KINDS[kind](n, rng(n + kind.length));
    const objectives = kind === 'grid' ? [PIPELINE_OBJECTIVE] : EXACT;
    const nPoints = xyz.length / 3;
    // delaunator: the triangulation everyone knows, alone.
    const coords = new Float64Array(2 * (xyz.length / 3));
    for (let i = 0; i < xyz.length / 3; ++i) coords[2 * i] = xyz[3 * i], coords[2 * i + 1] = xyz[3 * i + 1];
    const dl = median(Array.from({ length: reps }, () => time(() => new Delaunator(coords))[0]));
    // hodt native, same points.
    const file = join(tmp, 'points.bin');
    writeFileSync(file, Buffer.from(xyz.buffer));
    // Method auto: exact wherever it fits (every polynomial objective, and the
    // NP-hard ones unless a component is too wide), else the approximation.
    const nat = JSON.parse(spawnSync(`${root}/build/native/hodt_bench`, [file, String(reps), '--auto', ...objectives], { encoding: 'utf8', maxBuffer: 1 << 24 }).stdout);
    // hodt wasm: a fresh module per size so that its heap size is this run's peak.
    const module = await warmModule(objectives);
    const terrainMs = [], drainageMs = [], solveMs = Object.fromEntries(objectives.map((o) => [o, []]));
    let quads = 0, pipelineHeap = 0;
    const approximated = {};  // objective -> its answer when auto did not run exact
    for (let r = 0; r < reps; ++r) {
      const [ms, t] = time(() => module.fromPoints(xyz, false));
      terrainMs.push(ms);
      quads = t.numQuads();
      // The drainage network of the Delaunay triangulation, copied out as typed arrays.
      drainageMs.push(time(() => t.drainage(null))[0]);
      // The pipeline objective first, so that the heap's peak is the pipeline's.
      const order = [PIPELINE_OBJECTIVE, ...objectives.filter((o) => o !== PIPELINE_OBJECTIVE)];
      for (const o of order) {
        try {
          const [ms, sol] = time(() => t.solve(o, 'auto', 0.25, false, 1, undefined));
          solveMs[o].push(ms);
          if (sol.method !== 'exact') approximated[o] = { method: sol.method, value: sol.value, bound: sol.bound, details: sol.details };
        } catch { solveMs[o].push(NaN); }
        if (o === PIPELINE_OBJECTIVE && r === 0) pipelineHeap = module.heapSize();
      }
      t.delete();
    }
    const wasm = { terrain: median(terrainMs), drainage: median(drainageMs), objectives: Object.fromEntries(objectives.map((o) => [o, median(solveMs[o])])) };
    const heap = pipelineHeap;  // peak wasm memory after terrain + pipeline objective
    const pipeWasm = wasm.terrain + wasm.objectives[PIPELINE_OBJECTIVE];
    const pipeNative = nat.terrain + nat.objectives[PIPELINE_OBJECTIVE];
    const run = { kind, n: xyz.length / 3, quads, delaunatorMs: dl, native: nat, wasm, approximated, pipelineWasmMs: pipeWasm, pipelineNativeMs: pipeNative,
      wasmOverDelaunator: pipeWasm / dl, wasmOverNative: pipeWasm / pipeNative, heapBytesPerPoint: heap / (xyz.length / 3),
      drainage: { nativeMs: nat.drainage, wasmMs: wasm.drainage, wasmOverNative: wasm.drainage / nat.drainage, pits: nat.pits } };
    summary.runs.push(run);
    log(`\n${kind} n=${run.n} (${quads} quads): delaunator ${dl.toFixed(1)} ms | hodt terrain native ${nat.terrain.toFixed(1)} ms, wasm ${wasm.terrain.toFixed(1)} ms`);
    log(`  pipeline (terrain + ${PIPELINE_OBJECTIVE}): native ${pipeNative.toFixed(1)} ms, wasm ${pipeWasm.toFixed(1)} ms; wasm/delaunator ${run.wasmOverDelaunator.toFixed(2)}, wasm/native ${run.wasmOverNative.toFixed(2)}; wasm heap ${run.heapBytesPerPoint.toFixed(0)} B/point`);
    // Per point, terrain + solve, against uniform points of the same size.
    // (null for a refusal)
    const perPoint = (side, o) => (Number.isFinite(side.objectives[o]) ? (side.terrain + side.objectives[o]) / nPoints : NaN);
    if (kind === 'uniform') uniformPerPoint[n] = { native: nat, wasm, n: nPoints };
    const base = uniformPerPoint[n];
    // Drainage beside the solves: its time, wasm over native, and over the terrain's construction.
    if (kind === 'uniform' && Math.abs(run.n - 1e6) <= 1e4) summary.drainage_1M = run.drainage;
    log(`  ${`drainage (Delaunay, ${nat.pits} pits)`.padEnd(36)} native ${`${nat.drainage.toFixed(1)} ms`.padStart(12)}   wasm ${`${wasm.drainage.toFixed(1)} ms`.padStart(12)}` +
      `   wasm/native ${run.drainage.wasmOverNative.toFixed(2)}; / terrain: native ${(nat.drainage / nat.terrain).toFixed(3)}, wasm ${(wasm.drainage / wasm.terrain).toFixed(3)}`);
    run.perPointOverUniform = {};
    for (const o of objectives) {
      const ratio = REAL.has(kind) && base
        ? { native: perPoint(nat, o) / perPoint(base.native, o) || null, wasm: perPoint(wasm, o) / perPoint(base.wasm, o) || null }
        : null;
      if (ratio) run.perPointOverUniform[o] = ratio;
      const ms = (v) => (Number.isFinite(v) ? `${v.toFixed(1)} ms` : 'refused').padStart(12);
      const a = approximated[o];
      log(`  ${a ? 'auto ' : 'exact'} ${o.padEnd(30)} native ${ms(nat.objectives[o])}   wasm ${ms(wasm.objectives[o])}` +
        (ratio ? `   per point / uniform: native ${ratio.native?.toFixed(2) ?? 'refused'}, wasm ${ratio.wasm?.toFixed(2) ?? 'refused'}` : '') +
        (a ? `   (${a.method}: value ${a.value}, bound ${a.bound}; ${a.details.slice(0, 60)}...)` : ''));
    }
  }
}
if (onlyKinds) {
  rmSync(tmp, { recursive: true, force: true });
  writeFileSync(`${root}/bench-results.json`, JSON.stringify(summary, null, 2) + '\n');
  if (jsonOnly) console.log(JSON.stringify(summary));
  process.exit(0);
}
// The NP-hard objectives' approximation schemes on grids up to 200 x 200: DEM
// heights, and the paper's hardness surface f = xy - (x^2 + y^2) / 10 (one
// component of width about the grid side, which the roof dual now fixes whole
// for exact; here the scheme itself is measured).
const NP = ['max-convex-edges', 'min-mixed-vertices', 'minmax-degree'];
const saddle = (w) => {
  const p = new Float64Array(3 * w * w);
  for (let j = 0; j < w; ++j) for (let i = 0; i < w; ++i) { const x = i - w / 2, y = j - w / 2; p.set([i, j, x * y - (x * x + y * y) / 10], 3 * (j * w + i)); }
  return p;
};
summary.approx = [];
for (const [kind, make] of [['grid', (w) => KINDS.grid(w * w)], ['saddle', saddle]]) {
  for (const w of quick ? [50] : [50, 100, 200]) {
    const xyz = make(w);
    const file = join(tmp, 'points.bin');
    writeFileSync(file, Buffer.from(xyz.buffer));
    const nat = JSON.parse(spawnSync(`${root}/build/native/hodt_bench`, [file, '1', '--approx', ...NP], { encoding: 'utf8', maxBuffer: 1 << 24 }).stdout);
    const module = await warmModule(NP);
    const t = module.fromPoints(xyz, false);
    const row = { kind, n: w * w, quads: t.numQuads(), native: nat.objectives, wasm: {}, results: {} };
    for (const o of NP) {
      const [ms, s] = time(() => t.solve(o, 'approx', 0.25, false, 1, undefined));
      row.wasm[o] = ms;
      row.results[o] = { value: s.value, bound: s.bound, delaunay: s.delaunayValue, details: s.details };
    }
    t.delete();
    summary.approx.push(row);
    log(`\napprox (epsilon 0.25) on ${kind} ${w}x${w} (${row.quads} quads)`);
    for (const o of NP) {
      const r = row.results[o];
      log(`  ${o.padEnd(20)} native ${String(nat.objectives[o]?.toFixed(1)).padStart(8)} ms  wasm ${row.wasm[o].toFixed(1).padStart(8)} ms  value ${r.value} bound ${r.bound} (Delaunay ${r.delaunay}; ${r.details})`);
    }
  }
}
// Order k: every objective, orders 1..8 (bench/order_k.mjs).
summary.orderK = await runOrderK({ root, tmp, hodt: await loadHodt(), log, quick });
// Small terrains at orders 2..8: the slowest case per order (bench/small_inputs.mjs).
summary.smallInputs = await runSmallInputs({ root, tmp, hodt: await loadHodt(), log, quick });
// The CLI end to end, wasm against native (bench/cli_end_to_end.mjs).
if (!onlyKinds) summary.cliEndToEnd = runCliEndToEnd({ root, tmp, log, quick });
// Users' files end to end: a NODATA raster with and without its domain, 17-digit
// numbers, LAZ (bench/users_files.mjs).
if (!onlyKinds) summary.usersFiles = await runUsersFiles({ root, tmp, log, quick });
rmSync(tmp, { recursive: true, force: true });

const at = (kind, n) => summary.runs.find((r) => r.kind === kind && r.n >= n * 0.99 && r.n <= n * 1.01);
const big = at('uniform', 1e6);
summary.pipeline_1M_wasm_over_delaunator = big?.wasmOverDelaunator ?? null;
summary.pipeline_1M_wasm_over_native = big?.wasmOverNative ?? null;
summary.heap_bytes_per_point_1M = big?.heapBytesPerPoint ?? null;
// Live edits of a 10k-point terrain: one edit (move, add, delete in turn) through
// the terrain's live edit API, re-solve, take the triangles. In Node, next to a
// full rebuild per edit for comparison; then in Chromium (bench/edit.html, driven
// by Playwright), where the result also goes into a three.js geometry. The
// summary's edit_10k_* keys are the slower of the two objectives.
const EDIT_OBJECTIVES = ['min-local-minima', 'minmax-edge-area-ratio'];
{
  const hodt = await loadHodt();
  const quantile = (a, q) => [...a].sort((x, y) => x - y)[Math.floor(a.length * q)];
  summary.edit_10k_node = {};
  for (const objective of EDIT_OBJECTIVES) {
    const xyz = KINDS.dem(10000, rng(123));
    const r = rng(7), live = [], rebuilt = [];
    const terrain = hodt.terrain(xyz);
    for (let i = 0; i < (quick ? 60 : 260); ++i) {
      const k = Math.floor(r() * terrain.numInputPoints), p = terrain.points;
      const x = Math.min(1, Math.max(0, p[3 * k] + (r() - 0.5) * 0.01)), y = Math.min(1, Math.max(0, p[3 * k + 1] + (r() - 0.5) * 0.01));
      let t0 = performance.now();
      try {
        [() => terrain.movePoint(k, x, y, hill(x, y)), () => terrain.addPoint(x, y, hill(x, y)), () => terrain.removePoint(k)][i % 3]();
      } catch { continue; }  // a position already taken: nothing changed
      void terrain.solve(objective, { method: 'exact' }).triangles;
      const liveMs = performance.now() - t0;
      t0 = performance.now();
      const fresh = hodt.terrain(terrain.points);
      void fresh.solve(objective, { method: 'exact' }).triangles;
      fresh.dispose();
      if (i >= 60 || quick) live.push(liveMs), rebuilt.push(performance.now() - t0);
    }
    terrain.dispose();
    summary.edit_10k_node[objective] = { p50: quantile(live, 0.5), p95: quantile(live, 0.95), rebuildP50: quantile(rebuilt, 0.5) };
    log(`\nlive edit, 10k DEM points, ${objective} (Node): p50 ${quantile(live, 0.5).toFixed(1)} ms, p95 ${quantile(live, 0.95).toFixed(1)} ms; full rebuild instead: p50 ${quantile(rebuilt, 0.5).toFixed(1)} ms`);
  }
  const worst = (runs, key) => Math.max(...EDIT_OBJECTIVES.map((o) => runs[o][key]));
  try {
    const chromium = await measureEditsInChromium();
    summary.edit_10k_chromium = chromium;
    summary.edit_10k_p50_ms = worst(chromium, 'p50');
    summary.edit_10k_p95_ms = worst(chromium, 'p95');
    summary.edit_10k_measured_in = `chromium, ${chromium[EDIT_OBJECTIVES[0]].edits} edits per objective, live edit API, handed to three.js`;
    for (const o of EDIT_OBJECTIVES)
      log(`live edit in Chromium, ${o}, handed to three.js: p50 ${chromium[o].p50.toFixed(1)} ms, p95 ${chromium[o].p95.toFixed(1)} ms over ${chromium[o].edits} edits`);
  } catch (e) {
    summary.edit_10k_p50_ms = worst(summary.edit_10k_node, 'p50');
    summary.edit_10k_p95_ms = worst(summary.edit_10k_node, 'p95');
    summary.edit_10k_measured_in = `node (Chromium failed: ${e.message})`;
  }
}
writeFileSync(`${root}/bench-results.json`, JSON.stringify(summary, null, 2) + '\n');
if (jsonOnly) console.log(JSON.stringify(summary));
else log(`\nsummary written to bench-results.json`);
