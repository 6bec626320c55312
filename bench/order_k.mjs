// The order-k table of `npm run bench`: every objective at orders 1..8 on a real
// DEM (Maunga Whau, 87 x 61 cells of 10 m in projected coordinates: a grid, so
// cocircular everywhere), on a 10,000-point random sample of a smooth DEM, and on
// a DEM of your own and 10,000 points drawn from it (HODT_BENCH_DEM), the native
// CLI and the wasm library side by side: time, value, bound, Delaunay value.
import { spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { OBJECTIVES, hill, rng, runAlone } from './common.mjs';

function volcano() {
  const v = JSON.parse(readFileSync(new URL('../node_modules/vega-datasets/data/volcano.json', import.meta.url), 'utf8'));
  const p = new Float64Array(3 * v.width * v.height);
  for (let j = 0; j < v.height; ++j)
    for (let i = 0; i < v.width; ++i) p.set([2667400 + 10 * i, 6478700 - 10 * j, v.values[j * v.width + i]], 3 * (j * v.width + i));
  return p;
}

function demSample(n) {
  const r = rng(7);
  const p = new Float64Array(3 * n);
  for (let i = 0; i < n; ++i) { const x = r() * 1000, y = r() * 1000; p.set([x, y, hill(x / 1000, y / 1000) * 100 + r()], 3 * i); }
  return p;
}

const fmt = (v) => (v === null || v === undefined ? '-' : Number.isInteger(v) ? String(v) : v.toPrecision(6));

// A DEM of your own (HODT_BENCH_DEM=file: GeoTIFF, ESRI ASCII grid or x y z
// text), for the issue's "real DEM of 100,000 points and more" row: no such file
// comes with npm or Debian, so the benchmark runs it only when given one.
async function ownDem(hodt) {
  const path = process.env.HODT_BENCH_DEM;
  if (!path) return null;
  const bytes = new Uint8Array(readFileSync(path));
  const { readPointFile } = await import('../dist/loaders/index.js');
  const cloud = await readPointFile(bytes);
  const text = cloud ? null : hodt.readPoints(bytes, path);
  let [xyz, maxEdge] = cloud ? [cloud.xyz, cloud.maxEdge] : [text.points, text.maxEdge];
  const geographic = cloud?.crs === 'EPSG:4326';
  if (geographic) [xyz, maxEdge] = toLocalMetres(xyz, maxEdge);
  return [`${path} (${xyz.length / 3} points${geographic ? ', longitude and latitude to local metres' : ''}${maxEdge ? `, maxEdge ${maxEdge}` : ''})`, xyz, maxEdge];
}

// n of the DEM's points drawn at random (a fixed seed), for the issue's row of
// 10,000 real DEM points: the heights and the near-degenerate geometry of real
// data, unlike demSample's smooth function. Without the DEM's maxEdge (its
// cells' gaps do not apply to points this sparse).
function sampleOf([name, xyz], n) {
  const count = xyz.length / 3;
  const index = Array.from({ length: count }, (_, i) => i);
  const r = rng(11);
  for (let i = 0; i < Math.min(n, count); ++i) {
    const j = i + Math.floor(r() * (count - i));
    [index[i], index[j]] = [index[j], index[i]];
  }
  const out = new Float64Array(3 * Math.min(n, count));
  for (let i = 0; i < out.length / 3; ++i) out.set(xyz.subarray(3 * index[i], 3 * index[i] + 3), 3 * i);
  return [`${out.length / 3} points drawn at random from ${name}`, out];
}

// Longitude and latitude (WGS 84 degrees) to metres east and north of the
// points' centre, by the ellipsoid's radii of curvature there (an equirectangular
// projection: within a DEM tile, a few centimetres from a conformal one). Heights
// stay as they are. The geometry keeps the reader's rounding of the raster's
// cell centres, as a reprojected DEM does: near-degenerate, not an exact grid.
function toLocalMetres(xyz, maxEdge) {
  let lon = 0, lat = 0;
  const n = xyz.length / 3;
  for (let i = 0; i < xyz.length; i += 3) lon += xyz[i] / n, lat += xyz[i + 1] / n;
  const a = 6378137, e2 = 0.00669437999014, rad = Math.PI / 180, s = Math.sin(lat * rad);
  const east = (a / Math.sqrt(1 - e2 * s * s)) * Math.cos(lat * rad) * rad; // metres per degree
  const north = ((a * (1 - e2)) / (1 - e2 * s * s) ** 1.5) * rad;
  const out = new Float64Array(xyz.length);
  for (let i = 0; i < xyz.length; i += 3) out.set([(xyz[i] - lon) * east, (xyz[i + 1] - lat) * north, xyz[i + 2]], i);
  return [out, maxEdge ? maxEdge * Math.max(east, north) : maxEdge];
}

// only: which sets (volcano, sample, own-sample, own; all by default), orders and objectives.
export async function runOrderK({ root, tmp, hodt, log, quick, only = {} }) {
  const sets = [];
  if (!only.sets || only.sets.includes('volcano')) sets.push(['volcano DEM 87x61 (10 m grid, UTM-like)', volcano()]);
  if (!only.sets || only.sets.includes('sample')) sets.push(['DEM sample, 10,000 points', demSample(10000)]);
  const own = !only.sets || only.sets.includes('own') || only.sets.includes('own-sample') ? await ownDem(hodt) : null;
  if (own && (!only.sets || only.sets.includes('own-sample'))) sets.push(sampleOf(own, 10000));
  if (own && (!only.sets || only.sets.includes('own'))) sets.push(own);
  if (!own) log('\n(order k on a DEM of your own: HODT_BENCH_DEM=dem.tif npm run bench)');
  const orders = only.orders ?? (quick ? [1, 2, 4] : [1, 2, 3, 4, 5, 6, 7, 8]);
  const rows = [];
  for (const [name, xyz, maxEdge] of sets) {
    const file = join(tmp, `orderk-${rows.length}.txt`);
    let text = '';
    for (let i = 0; i < xyz.length; i += 3) text += `${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}\n`;
    writeFileSync(file, text);
    const terrain = hodt.terrain(xyz, { dedupe: 'first', maxEdge: maxEdge ?? null });
    const extra = ['--dedupe', 'first', ...(maxEdge ? ['--max-edge', String(maxEdge)] : [])];
    log(`\norder k on ${name}: time native / wasm (ms), value, bound (null: proven optimal), Delaunay value`);
    for (const objective of only.objectives ?? (quick ? ['min-local-minima', 'minmax-edge-area-ratio', 'min-mixed-vertices'] : OBJECTIVES)) {
      for (const order of orders) {
        const t0 = performance.now();
        const r = spawnSync(`${root}/build/native/hodt`, ['solve', file, '--objective', objective, '--order', String(order), ...extra], { encoding: 'utf8', maxBuffer: 1 << 26 });
        const nativeMs = performance.now() - t0;
        const row = { set: name, objective, order, nativeMs };
        if (r.status === 0) Object.assign(row, JSON.parse(r.stdout));
        else row.error = r.stderr.trim();
        const t1 = performance.now();
        try {
          const s = terrain.solve(objective, { order });
          row.wasmMs = performance.now() - t1;
          row.wasmValue = s.value;
        } catch (e) {
          row.wasmError = String(e.message);
        }
        rows.push(row);
        const wasmMs = row.wasmMs === undefined ? '-' : row.wasmMs.toFixed(0);
        log(`  k=${order} ${objective.padEnd(29)} ${nativeMs.toFixed(0).padStart(6)} / ${wasmMs.padStart(6)}  ${(row.method ?? 'error').padEnd(10)} value ${fmt(row.value).padEnd(12)} bound ${fmt(row.bound).padEnd(12)} Delaunay ${fmt(row.delaunayValue)}${row.error ? ` (${row.error})` : ''}${row.wasmError ? ` (wasm: ${row.wasmError})` : row.wasmValue !== undefined && row.wasmValue !== row.value ? ` (wasm value ${fmt(row.wasmValue)})` : ''}`);
      }
    }
    terrain.dispose();
  }
  return rows;
}

// Alone, after a build: `node bench/order_k.mjs --sets=volcano,own --orders=1,2,3,4
// --objectives=min-mixed-vertices` (each a comma list; all by default).
const arg = (name) => process.argv.find((a) => a.startsWith(`--${name}=`))?.slice(name.length + 3).split(',');
await runAlone(import.meta.url, (context) => runOrderK({
  ...context, quick: false, only: { sets: arg('sets'), orders: arg('orders')?.map(Number), objectives: arg('objectives') },
}));
