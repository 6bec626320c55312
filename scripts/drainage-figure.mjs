// The README's picture of water on a real survey, and its tables:
// `npm run figure:drainage` (after `npm run build`). Reads the LiDAR survey
// tests/fixtures-gis/lidar-point10.laz through hodt/loaders (its ground points),
// solves it with the built package for the fewest local minima at orders 1 to 4,
// and writes docs/drainage-lidar.svg (Delaunay beside the order-4 optimum: basins,
// flow lines, pits and outlets) and the tables of pits, outlets, basins and local
// minima into README.md and docs/api.md, for the survey and for the volcano DEM
// (tests/fixtures/volcano-jittered-60x60.txt: a DEM of whole metres sampled
// bilinearly, so its samples share heights wherever the DEM is flat).
//
//   node scripts/drainage-figure.mjs           prints the tables
//   node scripts/drainage-figure.mjs --write   writes the picture and the tables
//   node scripts/drainage-figure.mjs --check   exits 1 if either is stale
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadHodt } from 'hodt';
import { readPointFile } from 'hodt/loaders';
import {
  BASIN_COLORS,
  BASIN_OPACITY,
  basinSlots,
  FLOW_COLOR,
  flowWidth,
  majorityBasin,
  NO_BASIN_COLOR,
  OUTLET_COLOR,
  PIT_COLOR,
} from '../web/demo/src/teach/water/waterStyle.js';
import { updateBlocks } from './docBlocks.mjs';

const repo = fileURLToPath(new URL('../', import.meta.url));
const WRITER = 'scripts/drainage-figure.mjs';
export const LIDAR = 'tests/fixtures-gis/lidar-point10.laz';
export const VOLCANO = 'tests/fixtures/volcano-jittered-60x60.txt';
export const FIGURE = 'docs/drainage-lidar.svg';
/** The orders of the tables; the picture shows the last. */
export const ORDERS = [1, 2, 3, 4];
const OBJECTIVE = 'min-local-minima';

/**
 * One row of a table: a triangulation of the terrain and its drainage.
 * @typedef {{ order: number, triangles: Uint32Array, drainage: import('hodt').Drainage, localMinima: number, optimal: boolean }} Row
 */

/**
 * The Delaunay triangulation (order 0) and the optimum for the fewest local
 * minima at each order, with their drainage.
 * @param {import('hodt').Terrain} terrain
 * @returns {Row[]}
 */
export function drainageRows(terrain) {
  const row = (order, triangles, optimal) => ({
    order,
    triangles,
    drainage: terrain.drainage(triangles),
    localMinima: terrain.evaluateTriangles(triangles)[OBJECTIVE],
    optimal,
  });
  return [
    row(0, terrain.delaunay().triangles, true),
    ...ORDERS.map((k) => {
      const s = terrain.solve(OBJECTIVE, k > 1 ? { order: k } : {});
      return row(k, s.triangles, s.optimal);
    }),
  ];
}

/** The survey's ground points and the volcano DEM's points. */
export async function readTerrains() {
  const cloud = await readPointFile(readFileSync(join(repo, LIDAR)));
  if (!cloud) throw new Error(`${LIDAR}: not a LAS or LAZ file`);
  const hodt = await loadHodt();
  return {
    hodt,
    // As the CLI reads LAS/LAZ: returns that repeat a point's (x, y) are dropped.
    lidar: hodt.terrain(cloud.xyz, { dedupe: 'first' }),
    volcano: hodt.terrain(hodt.readPoints(readFileSync(join(repo, VOLCANO)), VOLCANO).points),
  };
}

const triangulationName = (order) => (order === 0 ? 'Delaunay' : `order ${order}, fewest local minima`);

/**
 * A Markdown table: pits, outlets, basins and local minima per row.
 * @param {Row[]} rows
 */
export function table(rows) {
  const lines = ['| triangulation | pits | outlets | basins | local minima |', '|---|---:|---:|---:|---:|'];
  for (const r of rows) {
    const { pits, outlets } = r.drainage;
    lines.push(`| ${triangulationName(r.order)} | ${pits.length} | ${outlets.length} | ${pits.length + outlets.length} | ${r.localMinima}${r.optimal ? '' : ' (not proven optimal)'} |`);
  }
  return lines.join('\n');
}

const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
const round = (v) => String(Math.round(v * 10) / 10);

/**
 * One pane of the figure: the triangles in their basin's colour, the edges,
 * the flow lines by log(accumulation), pits and outlets; `slots` colour a basin
 * by its pit or outlet (waterStyle.js).
 * @param {Float64Array} xyz
 * @param {Row} row
 * @param {Int32Array} slots
 * @param {(i: number) => number} X
 * @param {(i: number) => number} Y
 */
function pane(xyz, row, slots, X, Y) {
  const { triangles, drainage: d } = row;
  const out = [];
  const corner = (v) => `${round(X(v))} ${round(Y(v))}`;
  const tri = (t) => `M${corner(triangles[3 * t])}L${corner(triangles[3 * t + 1])}L${corner(triangles[3 * t + 2])}Z`;
  const fills = new Map();
  for (let t = 0; t < triangles.length / 3; t++) {
    const r = majorityBasin(triangles, d.basin, t);
    const color = r < 0 ? NO_BASIN_COLOR : BASIN_COLORS[slots[r]];
    fills.set(color, (fills.get(color) ?? '') + tri(t));
  }
  for (const [color, path] of [...fills].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))) {
    out.push(`<path fill="${color}"${color === NO_BASIN_COLOR ? '' : ` fill-opacity="${BASIN_OPACITY}"`} d="${path}"/>`);
  }
  const edges = new Set();
  let mesh = '';
  for (let k = 0; k < triangles.length; k++) {
    const a = triangles[k], b = triangles[k - (k % 3) + ((k % 3) + 1) % 3];
    const key = Math.min(a, b) * xyz.length + Math.max(a, b);
    if (edges.has(key)) continue;
    edges.add(key);
    mesh += `M${corner(a)}L${corner(b)}`;
  }
  out.push(`<path fill="none" stroke="#3c4844" stroke-opacity="0.25" stroke-width="0.5" d="${mesh}"/>`);
  // Flow lines grouped by width, thin first so the main streams lie on top.
  let most = 0;
  for (const a of d.accumulation) most = Math.max(most, a);
  const byWidth = new Map();
  d.downstream.forEach((to, from) => {
    if (to < 0) return;
    const w = round(flowWidth(d.accumulation[from], most));
    byWidth.set(w, (byWidth.get(w) ?? '') + `M${corner(from)}L${corner(to)}`);
  });
  for (const [w, path] of [...byWidth].sort(([a], [b]) => Number(a) - Number(b))) {
    out.push(`<path fill="none" stroke="${FLOW_COLOR}" stroke-linecap="round" stroke-width="${w}" d="${path}"/>`);
  }
  for (const v of d.outlets) out.push(`<rect x="${round(X(v) - 3.5)}" y="${round(Y(v) - 3.5)}" width="7" height="7" fill="${OUTLET_COLOR}" stroke="#fff" stroke-width="1.2"/>`);
  for (const v of d.pits) out.push(`<circle cx="${round(X(v))}" cy="${round(Y(v))}" r="4.5" fill="${PIT_COLOR}" stroke="#fff" stroke-width="1.2"/>`);
  return out;
}

/**
 * The figure: the Delaunay triangulation's drainage beside the optimum's, one
 * colour per Delaunay basin, so a basin the optimum merges takes its neighbour's.
 * @param {Float64Array} xyz
 * @param {Row} delaunay
 * @param {Row} optimum
 */
export function figure(xyz, delaunay, optimum) {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (let i = 0; i < xyz.length; i += 3) {
    x0 = Math.min(x0, xyz[i]), x1 = Math.max(x1, xyz[i]);
    y0 = Math.min(y0, xyz[i + 1]), y1 = Math.max(y1, xyz[i + 1]);
  }
  const inner = 440, margin = 14, head = 46, foot = 44;
  const scale = inner / Math.max(x1 - x0, y1 - y0);
  const w = (x1 - x0) * scale + 2 * margin, h = (y1 - y0) * scale;
  const width = 2 * w, height = head + h + margin + foot;
  const slots = basinSlots(delaunay.triangles, delaunay.drainage.basin, BASIN_COLORS.length);
  const Y = (i) => head + (y1 - xyz[3 * i + 1]) * scale;
  const counts = (r) => `${plural(r.drainage.pits.length, 'pit')}, ${plural(r.drainage.outlets.length, 'outlet')}, ${plural(r.drainage.pits.length + r.drainage.outlets.length, 'basin')}; ${plural(r.localMinima, 'local minimum').replace(/minimums$/, 'minima')}`;
  const out = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${round(width)}" height="${round(height)}" viewBox="0 0 ${round(width)} ${round(height)}" font-family="system-ui, sans-serif">`,
    `<title>Drainage of a LiDAR survey: Delaunay and the order-${optimum.order} triangulation with the fewest local minima</title>`,
    `<desc>${xyz.length / 3} ground points of ${LIDAR}. Triangles in the colour of the basin two of their corners drain to, flow lines wider with log(accumulation), pits red, outlets blue. Written by ${WRITER}.</desc>`,
    `<rect width="100%" height="100%" fill="#fff"/>`,
  ];
  for (const [k, row] of [delaunay, optimum].entries()) {
    const left = k * w + margin;
    const X = (i) => left + (xyz[3 * i] - x0) * scale;
    out.push(`<text x="${round(left)}" y="18" font-size="14" font-weight="600">${row.order === 0 ? 'Delaunay' : `Order ${row.order}, fewest local minima`}</text>`);
    out.push(`<text x="${round(left)}" y="36" font-size="12" fill="#4a5753">${counts(row)}</text>`);
    out.push(...pane(xyz, row, slots, X, Y));
  }
  out.push(
    `<text x="${margin}" y="${round(height - 26)}" font-size="11" fill="#4a5753">Colour: the Delaunay basin where the water ends; a merged basin takes the colour of the one it joins.</text>`,
    `<text x="${margin}" y="${round(height - 10)}" font-size="11" fill="#4a5753">Lines: flow to the steepest lower neighbour, wider with log(accumulation). Red: pit. Square: outlet.</text>`,
    '</svg>',
    '',
  );
  return out.join('\n');
}

/** The picture and the docs' blocks, from the package as built now. */
export async function drainageFigure() {
  const { lidar, volcano } = await readTerrains();
  try {
    const lidarRows = drainageRows(lidar);
    const volcanoRows = drainageRows(volcano);
    const lidarTable = table(lidarRows), volcanoTable = table(volcanoRows);
    const svg = figure(lidar.points, lidarRows[0], lidarRows.at(-1));
    return {
      lidarRows,
      volcanoRows,
      lidarTable,
      volcanoTable,
      svg,
      blocks: {
        'README.md': { 'drainage-lidar': lidarTable, 'drainage-volcano': volcanoTable },
        'docs/api.md': { 'drainage-lidar': lidarTable },
      },
    };
  } finally {
    lidar.dispose();
    volcano.dispose();
  }
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const mode = process.argv[2];
  const f = await drainageFigure();
  console.log(`${LIDAR} (ground points):\n\n${f.lidarTable}\n\n${VOLCANO}:\n\n${f.volcanoTable}`);
  if (mode === '--write' || mode === '--check') {
    const stale = updateBlocks(repo, WRITER, f.blocks, { write: mode === '--write' });
    let svgNow = '';
    try {
      svgNow = readFileSync(join(repo, FIGURE), 'utf8');
    } catch {}
    if (svgNow !== f.svg) {
      stale.push(FIGURE);
      if (mode === '--write') writeFileSync(join(repo, FIGURE), f.svg);
    }
    if (mode === '--check' && stale.length) {
      console.error(`${stale.join(', ')}: not what the package computes now; run \`npm run figure:drainage\``);
      process.exit(1);
    }
  }
}
