#!/usr/bin/env node
// A smooth terrain as an ESRI ASCII grid with NODATA: a lake inside and a ragged
// region along one border, the shape of a real clipped DEM. Rasters with NODATA
// get the default domain (maxEdge = 3 cells), so this times a solve with a domain
// against the same points with `--max-edge none`.
//
//   node bench/nodata_raster.mjs out.asc [cols] [rows] [seed]
//
// Defaults: 400 x 420 cells, seed 1. The heights are a sum of smooth waves with a
// small seeded jitter (so that most quads are flippable, as in a real DEM); the
// lake is an ellipse in the middle and the border region a wavy band along the
// west edge, both NODATA (-9999).
import { writeFileSync } from 'node:fs';

const [out, colsArg, rowsArg, seedArg] = process.argv.slice(2);
if (!out) {
  console.error('usage: node bench/nodata_raster.mjs out.asc [cols] [rows] [seed]');
  process.exit(2);
}
const cols = Number(colsArg ?? 400), rows = Number(rowsArg ?? 420), seed = Number(seedArg ?? 1);
if (!(Number.isInteger(cols) && cols >= 8 && Number.isInteger(rows) && rows >= 8 && Number.isInteger(seed)))
  throw new Error(`cols and rows must be integers >= 8 and seed an integer, got ${colsArg} ${rowsArg} ${seedArg}`);

// mulberry32: a small seeded generator, so that a size and seed give one file.
let state = seed >>> 0;
function random() {
  state = (state + 0x6d2b79f5) >>> 0;
  let t = state;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
}

const cell = 10, nodata = -9999;
const lines = [
  `ncols ${cols}`,
  `nrows ${rows}`,
  'xllcorner 500000.0',
  'yllcorner 4100000.0',
  `cellsize ${cell}`,
  `NODATA_value ${nodata}`,
];
for (let r = 0; r < rows; ++r) {
  const row = new Array(cols);
  for (let c = 0; c < cols; ++c) {
    const x = c / cols, y = r / rows;
    const lake = ((x - 0.55) / 0.18) ** 2 + ((y - 0.5) / 0.12) ** 2 < 1;
    const border = x < 0.06 + 0.04 * Math.sin(9 * y) + 0.02 * Math.sin(31 * y);
    if (lake || border) {
      row[c] = nodata;
      continue;
    }
    const z =
      300 + 80 * Math.sin(3.1 * x + 1.3) * Math.cos(2.3 * y) + 25 * Math.sin(11 * x * y + 0.4) +
      6 * Math.cos(17 * x - 13 * y) + 0.6 * (random() - 0.5);
    row[c] = z.toFixed(2);
  }
  lines.push(row.join(' '));
}
writeFileSync(out, lines.join('\n') + '\n');
