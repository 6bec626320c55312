/// <reference lib="webworker" />
// The solver worker: builds the terrain from the points with the public API and
// solves one objective, so that long runs never freeze the page. Cancelling a run
// terminates this worker (the page starts a new one).
import { loadHodt, type ProgressInfo } from 'hodt';
import type { SolveRequest, WorkerReply } from './protocol.ts';

const scope = self as unknown as DedicatedWorkerGlobalScope;
const hodt = loadHodt();
const reply = (message: WorkerReply) => scope.postMessage(message);

scope.onmessage = async (event: MessageEvent<SolveRequest>) => {
  const { id, points, objective, method, epsilon, order, maxEdge = null, trace, explain } = event.data;
  try {
    const terrain = (await hodt).terrain(points, { maxEdge });
    let last = 0;
    let phase = '';
    const progress = (_done: number, _total: number, info: ProgressInfo) => {
      const now = performance.now();
      if (now - last < 100 && info.phase === phase) return; // a few updates a second are plenty, and each new phase
      last = now;
      phase = info.phase;
      reply({ type: 'progress', id, info });
    };
    try {
      // Order k >= 2 chooses its method itself: the library refuses one.
      const options = order > 1 ? { order, progress } : { method, epsilon, trace, progress };
      if (explain) {
        const explanation = terrain.explain(objective, options);
        reply({ type: 'solved', id, solution: explanation.solution, explanation });
      } else {
        reply({ type: 'solved', id, solution: terrain.solve(objective, options) });
      }
    } finally {
      terrain.dispose();
    }
  } catch (e) {
    const error = e instanceof Error ? e : new Error(String(e));
    reply({ type: 'failed', id, name: error.name, message: error.message });
  }
};
