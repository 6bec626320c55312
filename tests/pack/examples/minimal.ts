// A strict project with no @types/node, no esnext lib and skipLibCheck off: hodt's
// declarations must still compile.
import { type Hodt, loadHodt, type Solution, type Terrain } from 'hodt';

const hodt: Hodt = await loadHodt();
const terrain: Terrain = hodt.terrain([0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 0]);
const best: Solution = terrain.solve('min-local-minima');
document.title = `${best.triangles.length / 3} triangles`;
terrain.dispose();
