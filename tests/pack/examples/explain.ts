// docs/api.md, "Explaining a solve".
import { loadHodt, type Explanation } from 'hodt';

const hodt = await loadHodt();
using terrain = hodt.terrain([0, 0, 1, 4, 0, 2, 0, 4, 0, 4, 4, 3, 1.5, 2.2, 5, 2.6, 1.4, 1, 2, 3, 2]);
const e: Explanation = terrain.explain('minmax-edge-normal-angle');
for (const test of e.search?.tests ?? []) {
  const verdict = test.satisfiable ? 'yes' : `no (${test.conflicts.length} conflicts)`;
  console.log(`t = ${test.threshold}: ${test.clauses.length / 2} clauses, ${verdict}`);
}
const k3 = terrain.explain('min-local-minima', { order: 3 }).regions!;
console.log(`${k3.fixed.length / 2} fixed edges, ${k3.triangulations.length} regions`);
