// docs/api.md "In a Web Worker": solve off the main thread. The page creates it with
//   new Worker(new URL('./worker.ts', import.meta.url), { type: 'module' })
// posts { points, objective }, gets progress messages, then { triangles, value }
// or { error }. worker.terminate() stops a run at any time.
import { loadHodt, type ObjectiveId } from 'hodt';

export interface SolveRequest {
  points: Float64Array;
  objective: ObjectiveId;
}
export type SolveReply =
  | { kind: 'progress'; done: number; total: number; phase: string }
  | { kind: 'solved'; triangles: Uint32Array; value: number; delaunayValue: number; optimal: boolean }
  | { kind: 'failed'; name: string; message: string };

const ready = loadHodt(); // starts loading as soon as the worker starts
const reply = (message: SolveReply, transfer: Transferable[] = []) => self.postMessage(message, { transfer });

self.onmessage = async ({ data }: MessageEvent<SolveRequest>) => {
  try {
    const hodt = await ready;
    const terrain = hodt.terrain(data.points);
    try {
      const best = terrain.solve(data.objective, {
        progress: (done, total, { phase }) => reply({ kind: 'progress', done, total, phase }),
      });
      const { triangles, value, delaunayValue, optimal } = best;
      reply({ kind: 'solved', triangles, value, delaunayValue, optimal }, [triangles.buffer]);
    } finally {
      terrain.dispose();
    }
  } catch (e) {
    const { name, message } = e instanceof Error ? e : new Error(String(e));
    reply({ kind: 'failed', name, message });
  }
};
