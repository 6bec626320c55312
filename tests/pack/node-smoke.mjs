// Copied into the temporary project and run there with plain Node:
// `node node-smoke.mjs POINTS [three]`. Uses the installed package by its name, as
// a user would, and prints one JSON line.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { CancelledError, HodtError, InputError, loadHodt, OBJECTIVE_IDS } from 'hodt';
import { setTriangles, terrainGeometry } from 'hodt/three'; // must not need three itself

const [file, mode] = process.argv.slice(2);
const hodt = await loadHodt();
const { points } = hodt.readPoints(readFileSync(file, 'utf8'), file);
const terrain = hodt.terrain(points);
const values = {};
for (const id of OBJECTIVE_IDS) values[id] = terrain.solve(id).value;
const best = terrain.solve('min-local-minima');

let aborted = null;
try {
  terrain.solve('max-convex-edges', { signal: AbortSignal.abort() });
} catch (e) {
  aborted = { cancelled: e instanceof CancelledError, name: e.name };
}
let input = null;
try {
  hodt.terrain([0, 0, 0, 1, 0, 0, 0, Number.NaN, 0]);
} catch (e) {
  input = { input: e instanceof InputError, hodt: e instanceof HodtError, name: e.name, message: e.message };
}

let three = null;
if (mode === 'three') {
  const THREE = await import('three');
  const geometry = terrainGeometry(THREE, terrain.points, terrain.delaunay().triangles);
  setTriangles(geometry, best.triangles);
  three = { isBufferGeometry: geometry.isBufferGeometry, index: geometry.getIndex().count, position: geometry.getAttribute('position').count };
}
const out = {
  node: process.versions.node,
  resolved: createRequire(import.meta.url).resolve('hodt'),
  points: terrain.numPoints,
  quads: terrain.numQuads,
  triangles: best.triangles.length / 3,
  isUint32: best.triangles instanceof Uint32Array,
  value: best.value,
  delaunayValue: best.delaunayValue,
  optimal: best.optimal,
  values,
  aborted,
  input,
  three,
};
terrain.dispose();
console.log(JSON.stringify(out));
