// The types say what runs: items of your own through accessors typed by the
// item, and no point without a height.
import { loadHodt, solveInWorker } from 'hodt';

const hodt = await loadHodt();
const rows = [
  { east: 0, north: 0, h: 1 },
  { east: 4, north: 0, h: 2 },
  { east: 0, north: 4, h: 0 },
  { east: 4, north: 4, h: 3 },
];
using terrain = hodt.terrain(rows, { x: (r) => r.east, y: (r) => r.north, z: (r) => r.h, dedupe: 'first' });
const inWorker = await solveInWorker(rows, 'min-local-minima', { terrain: { x: (r) => r.east, y: (r) => r.north, z: (r) => r.h } });
console.log(terrain.numPoints, inWorker.value);

// @ts-expect-error: the rows have no field `height`
hodt.terrain(rows, { x: (r) => r.east, y: (r) => r.north, z: (r) => r.height });
// @ts-expect-error: items of your own need the accessors
hodt.terrain(rows);
// @ts-expect-error: all three accessors
hodt.terrain(rows, { x: (r) => r.east, y: (r) => r.north });
// @ts-expect-error: [x, y] has no height
hodt.terrain([[0, 0], [1, 0], [0, 1]]);
// @ts-expect-error: [x, y] has no height, in a worker either
void solveInWorker([[0, 0], [1, 0], [0, 1]], 'min-local-minima');
hodt.terrain([[0, 0, 0], [1, 0, 0], [0, 1, 1, 99]]).dispose(); // a fourth coordinate (a measure) is ignored
