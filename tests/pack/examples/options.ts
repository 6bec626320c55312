// docs/api.md "Solving": options, cancellation, errors, ownership.
import { CancelledError, HodtError, InputError, LimitError, loadHodt, type Solution } from 'hodt';

const hodt = await loadHodt();
const points = [{ x: 0, y: 0, z: 1 }, { x: 1, y: 0, z: 2 }, { x: 0, y: 1, z: 0 }, { x: 1, y: 1, z: 3 }, { x: 0.4, y: 0.6, z: 5 }];
const terrain = hodt.terrain(points, { dedupe: 'first' });
try {
  const controller = new AbortController();
  const deadline = performance.now() + 2000;
  const best: Solution = terrain.solve('max-convex-edges', {
    method: 'auto',
    epsilon: 0.1,
    order: 1,
    signal: controller.signal,
    progress: (done, total) => {
      console.log(`${done} / ${total}`);
      return performance.now() < deadline; // false cancels
    },
  });
  console.log(best.value, best.delaunayValue, best.optimal, best.bound, best.triangles.length / 3);
  const { vertexClass, degree } = terrain.measures(best.choice); // per point, like the triangles
  console.log(vertexClass[4], degree[4], terrain.evaluate(best.choice)['max-convex-edges']);
} catch (e) {
  if (e instanceof CancelledError) console.log('stopped', e.cause);
  else if (e instanceof LimitError) console.log('refused:', e.message);
  else if (e instanceof InputError) console.log('bad input:', e.message);
  else if (e instanceof HodtError) console.log(e.name, e.message);
  else throw e;
} finally {
  terrain.dispose(); // frees the wasm memory; the arrays you got stay valid
}
