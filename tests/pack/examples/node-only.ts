// Compiled by tsconfig.node-only.json: the types a Node-only project sees.
import { type LoadOptions, loadHodt, type SolvedBy, type Terrain } from 'hodt';

const options: LoadOptions = {};
const hodt = await loadHodt(options);
const terrain: Terrain = hodt.terrain([
  [0, 0, 0],
  [1, 0, 0],
  [0, 1, 1],
  [1, 1, 0],
]);
const by: SolvedBy = terrain.solve('min-local-minima', { method: 'auto' }).method;
// @ts-expect-error: Solution.method is a union, not any string
const wrong: typeof by = 'simplex';
console.log(by, wrong, terrain.points.length);
terrain.dispose();
