// Benchmark rows on the files GIS users bring, each end to end (read the file,
// build, solve, print the JSON) by the native CLI (build/native/hodt) and by the
// npm CLI (`node dist/cli.js`, what `npx hodt` runs), as ratios:
// - a UTM raster with NODATA (an inlet from the east edge, a lake, two corners),
//   its default domain (3 cells) against `--max-edge none`, at order 1 and 4; the
//   npm CLI reads it as GeoTIFF (Float32, GDAL_NODATA), the native one as the same
//   cells in an ESRI ASCII grid;
// - CSVs of 100,000 and 1,000,000 points written as numpy's savetxt(fmt='%.17g')
//   writes them (--quick: the first);
// - a LAZ point cloud (the laz-perf test set in tests/fixtures-gis: laz-perf's npm
//   package decodes but cannot write LAZ, so no larger one is made); the native
//   CLI reads the same points as text.
// Wall time of the whole process, the fastest of 3 runs (one when it takes over 5 s). Run alone with
// `node bench/users_files.mjs [--quick]`.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { writeArrayBuffer } from 'geotiff';

const NODATA = -9999;

// Heights of smooth hills over a w x h raster of 2.5 m cells at (500000, 4100000)
// in UTM 33N, as float32 (what the GeoTIFF holds), with the fixture's gaps scaled
// (tests/fixtures-gis/dem-utm-inlet-nodata.asc): NODATA in an inlet, a lake and
// two corners. Row 0 is the northernmost.
function nodataRaster(w, h) {
  const z = new Float32Array(w * h);
  let gaps = 0;
  for (let r = 0; r < h; ++r)
    for (let c = 0; c < w; ++c) {
      const inlet = r >= 0.3 * h && r < 0.74 * h && c >= 0.57 * w;
      const lake = r >= 0.16 * h && r < 0.27 * h && c >= 0.27 * w && c < 0.4 * w;
      const corner = c + r < 0.15 * w || (w - 1 - c) + (h - 1 - r) < 0.1 * w;
      const x = c / w, y = r / h;
      const v = 300 + 45 * Math.sin(5.1 * x + 1) * Math.cos(3.7 * y) + 12 * Math.sin(17 * x * y + 2) + 0.37 * ((c * 7919 + r * 104729) % 101) / 101;
      z[r * w + c] = inlet || lake || corner ? NODATA : Math.round(v * 100) / 100;
      if (inlet || lake || corner) ++gaps;
    }
  return { w, h, z, cell: 2.5, x0: 500000, y0: 4100000, gaps };
}

function writeAsciiGrid(path, { w, h, z, cell, x0, y0 }) {
  const lines = [`ncols ${w}`, `nrows ${h}`, `xllcorner ${x0}`, `yllcorner ${y0}`, `cellsize ${cell}`, `NODATA_value ${NODATA}`];
  for (let r = 0; r < h; ++r) lines.push(Array.from(z.subarray(r * w, (r + 1) * w), String).join(' '));
  writeFileSync(path, lines.join('\n') + '\n');
}

function writeGeoTIFF(path, { w, h, z, cell, x0, y0 }) {
  const tiff = writeArrayBuffer(z, {
    width: w, height: h, BitsPerSample: [32], SampleFormat: [3],
    ModelPixelScale: [cell, cell, 0], ModelTiepoint: [0, 0, 0, x0, y0 + h * cell, 0],
    GTModelTypeGeoKey: 1, GTRasterTypeGeoKey: 1, ProjectedCSTypeGeoKey: 32633, GDAL_NODATA: `${NODATA}\0`,
  });
  writeFileSync(path, new Uint8Array(tiff));
}

// C's printf("%.17g"): 17 significant digits, trailing zeros dropped, an exponent
// below 1e-4 and from 1e17.
function g17(v) {
  if (v === 0) return '0';
  const e = Math.floor(Math.log10(Math.abs(v)));
  if (e < -4 || e >= 17) {
    const [m, x] = v.toExponential(16).split('e');
    const mant = m.replace(/\.?0+$/, '');
    const ex = Number(x);
    return `${mant}e${ex < 0 ? '-' : '+'}${String(Math.abs(ex)).padStart(2, '0')}`;
  }
  const s = v.toPrecision(17);
  return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
}

// DEM-like scattered points over a square kilometre of UTM coordinates.
function write17DigitCsv(path, n) {
  let s = 56;
  const r = () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
  const lines = [];
  for (let i = 0; i < n; ++i) {
    const u = r(), v = r();
    const z = 300 + 40 * Math.sin(6 * u) * Math.cos(4 * v) + 3 * r();
    lines.push(`${g17(500000 + 1000 * u)} ${g17(4100000 + 1000 * v)} ${g17(z)}`);
  }
  writeFileSync(path, lines.join('\n') + '\n');
}

export async function runUsersFiles({ root, tmp, log, quick }) {
  const runs = quick ? 1 : 3;
  const native = [join(root, 'build/native/hodt')], npm = ['node', join(root, 'dist/cli.js')];
  const fastest = (cli, args) => {
    let best = Infinity, json;
    for (let k = 0; k < runs; ++k) {
      const t0 = performance.now();
      const p = spawnSync(cli[0], [...cli.slice(1), ...args, '--quiet'], { encoding: 'utf8', maxBuffer: 1 << 30 });
      const ms = performance.now() - t0;
      if (p.status !== 0) throw new Error(`${cli.join(' ')} ${args.join(' ')}: ${p.stderr}`);
      if (ms < best) (best = ms), (json = JSON.parse(p.stdout));
      if (best > 5000) break;  // (a long run varies little; repeating it would double the bench)
    }
    return { ms: best, readMs: json.times?.readMs, value: json.value, optimal: json.optimal };
  };
  const row = (label, nativeArgs, npmArgs) => {
    const n = fastest(native, nativeArgs), w = fastest(npm, npmArgs);
    return { label, native: n, npm: w, npmOverNative: w.ms / n.ms };
  };
  const out = { nodataRaster: [], csv17: null, laz: null };
  const fmt = (ms) => (ms >= 1000 ? `${(ms / 1000).toFixed(2)} s` : `${ms.toFixed(0)} ms`);
  log(`\nUsers' files, end to end (native CLI / npm CLI, fastest of ${runs}):`);
  // What every run of each CLI costs before it reads a file (the npm CLI: Node, the wasm module).
  const startup = (cli) => {
    let best = Infinity;
    for (let k = 0; k < runs; ++k) {
      const t0 = performance.now();
      spawnSync(cli[0], [...cli.slice(1), '--version']);
      best = Math.min(best, performance.now() - t0);
    }
    return best;
  };
  out.startupMs = { native: startup(native), npm: startup(npm) };
  log(`startup (hodt --version): native ${fmt(out.startupMs.native)}, npm ${fmt(out.startupMs.npm)}`);

  // The NODATA raster.
  const raster = nodataRaster(quick ? 80 : 200, quick ? 60 : 150);
  const asc = join(tmp, 'dem-nodata.asc'), tif = join(tmp, 'dem-nodata.tif');
  writeAsciiGrid(asc, raster);
  writeGeoTIFF(tif, raster);
  out.rasterCells = raster.w * raster.h - raster.gaps;
  log(`NODATA raster ${raster.w} x ${raster.h} (${out.rasterCells} cells with data; npm CLI: GeoTIFF, native: ASCII grid), domain / no domain:`);
  // (max-convex-edges at order 4 takes half a minute without the domain: left out)
  const objectives = { 1: ['min-local-minima', 'minmax-edge-area-ratio', 'max-convex-edges'], 4: ['min-local-minima', 'minmax-edge-area-ratio'] };
  for (const order of [1, 4])
    for (const objective of quick ? ['min-local-minima'] : objectives[order]) {
      const args = (file, extra) => ['solve', file, '--objective', objective, '--order', String(order), ...extra];
      const domain = row('domain', args(asc, []), args(tif, []));
      const none = row('none', args(asc, ['--max-edge', 'none']), args(tif, ['--max-edge', 'none']));
      const r = { order, objective, domain, none, domainOverNone: { native: domain.native.ms / none.native.ms, npm: domain.npm.ms / none.npm.ms } };
      out.nodataRaster.push(r);
      log(`  order ${order} ${objective.padEnd(24)} domain: native ${fmt(domain.native.ms)}, npm ${fmt(domain.npm.ms)} (${domain.npmOverNative.toFixed(2)}x); ` +
        `none: native ${fmt(none.native.ms)}, npm ${fmt(none.npm.ms)} (${none.npmOverNative.toFixed(2)}x); ` +
        `domain / none: native ${r.domainOverNone.native.toFixed(2)}x, npm ${r.domainOverNone.npm.toFixed(2)}x`);
    }

  // 17 significant digits, at two sizes: each CLI's startup (above) is a fixed
  // cost, so the ratio without it is printed too.
  out.csv17 = [];
  for (const n17 of quick ? [100000] : [100000, 1000000]) {
    const csv = join(tmp, `points-17-digits-${n17}.txt`);
    write17DigitCsv(csv, n17);
    const solve17 = ['solve', csv, '--objective', 'min-local-minima'];
    const r = { points: n17, ...row('17 digits', solve17, solve17) };
    r.npmOverNativeLessStartup = (r.npm.ms - out.startupMs.npm) / (r.native.ms - out.startupMs.native);
    out.csv17.push(r);
    rmSync(csv);
    log(`CSV of ${n17} points with 17 significant digits (numpy savetxt '%.17g'), solve min-local-minima: native ${fmt(r.native.ms)} ` +
      `(read ${fmt(r.native.readMs)}), npm ${fmt(r.npm.ms)} (read ${fmt(r.npm.readMs)}): npm / native ${r.npmOverNative.toFixed(2)}x, ` +
      `${r.npmOverNativeLessStartup.toFixed(2)}x less each CLI's startup`);
  }

  // LAZ: the npm CLI decodes it; the native CLI reads the decoded points as text.
  const lazPath = join(root, 'tests/fixtures-gis/lidar-point10.laz');
  const { readLAS } = await import(join(root, 'dist/loaders/index.js'));
  const cloud = await readLAS(readFileSync(lazPath));
  const lazText = join(tmp, 'lidar-point10.txt');
  const lines = [];
  for (let i = 0; i < cloud.xyz.length; i += 3) lines.push(`${cloud.xyz[i]} ${cloud.xyz[i + 1]} ${cloud.xyz[i + 2]}`);
  writeFileSync(lazText, lines.join('\n') + '\n');
  const lazArgs = (file) => ['solve', file, '--objective', 'min-local-minima', '--dedupe', 'first'];
  out.laz = { points: cloud.xyz.length / 3, ...row('LAZ', lazArgs(lazText), lazArgs(lazPath)) };
  log(`LAZ ${out.laz.points} points (tests/fixtures-gis/lidar-point10.laz), solve min-local-minima: native ${fmt(out.laz.native.ms)} (as text), ` +
    `npm ${fmt(out.laz.npm.ms)}: npm / native ${out.laz.npmOverNative.toFixed(2)}x`);
  return out;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const root = fileURLToPath(new URL('..', import.meta.url));
  const tmp = mkdtempSync(join(tmpdir(), 'hodt-users-files-'));
  try {
    const out = await runUsersFiles({ root, tmp, log: console.log, quick: process.argv.includes('--quick') });
    if (process.argv.includes('--json')) console.log(JSON.stringify(out));
  } finally {
    rmSync(tmp, { recursive: true, force: true });
  }
}
