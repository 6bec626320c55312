// docs/api.md "Live edits".
import { loadHodt } from 'hodt';

const hodt = await loadHodt();
const terrain = hodt.terrain(new Float64Array([0, 0, 1, 4, 0, 2, 0, 4, 0, 4, 4, 1, 2, 2, 3]));
terrain.movePoint(4, 2.5, 1.5, 0.5); // drag the middle point
const added = terrain.addPoint(1, 3, 2); // 5
terrain.removePoint(0); // the old point 1 is now point 0
console.log(added, terrain.numInputPoints, terrain.solve('min-local-minima').value);
terrain.dispose();
