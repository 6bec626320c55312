import { readFileSync } from 'node:fs';
import { loadHodt } from 'hodt';

const hodt = await loadHodt(); // finds and loads hodt.wasm once
const { points } = hodt.readPoints(readFileSync(process.argv[2] ?? 'points.csv', 'utf8'));
const terrain = hodt.terrain(points); // wasm memory: dispose() when done
try {
  const best = terrain.solve('min-local-minima');
  console.log(`${terrain.numQuads} flippable quads; local minima: Delaunay ${best.delaunayValue}, optimal ${best.value}`);
  console.log(best.triangles); // Uint32Array: 3 point indices per triangle
} finally {
  terrain.dispose();
}
