import type { Explanation, Method, ObjectiveId, ProgressInfo, Solution } from 'hodt';
import type { SolveRequest, WorkerReply } from './protocol.ts';

export type SolveOutcome =
  | { status: 'solved'; solution: Solution; explanation?: Explanation }
  | { status: 'failed'; name: string; message: string }
  | { status: 'cancelled' };

export interface SolveJob {
  points: Float64Array;
  objective: ObjectiveId;
  method: Method;
  epsilon: number;
  order: number;
  /** The domain (Terrain.maxEdge); absent or null: none. */
  maxEdge?: number | null;
  trace?: boolean;
  /** Through terrain.explain (the outcome then carries the explanation). */
  explain?: boolean;
}

/** Runs one solve at a time in a Web Worker. A new solve or cancel() while one
 * runs terminates the worker (the only way to stop wasm mid-run) and starts a
 * fresh one; the superseded run resolves as cancelled. */
export interface SolverClient {
  solve(job: SolveJob, onProgress?: (info: ProgressInfo) => void): Promise<SolveOutcome>;
  cancel(): void;
  readonly busy: boolean;
}

export function createSolverClient(): SolverClient {
  let worker = spawn();
  let nextId = 1;
  let pending: { id: number; resolve: (o: SolveOutcome) => void; onProgress?: (info: ProgressInfo) => void } | null = null;

  function spawn(): Worker {
    const w = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'hodt-solver' });
    w.onmessage = (event: MessageEvent<WorkerReply>) => {
      const r = event.data;
      if (!pending || pending.id !== r.id) return;
      if (r.type === 'progress') {
        pending.onProgress?.(r.info);
        return;
      }
      const { resolve } = pending;
      pending = null;
      resolve(r.type === 'solved' ? { status: 'solved', solution: r.solution, explanation: r.explanation } : { status: 'failed', name: r.name, message: r.message });
    };
    w.onerror = (event) => {
      event.preventDefault();
      const p = pending;
      pending = null;
      p?.resolve({ status: 'failed', name: 'WorkerError', message: event.message || 'the solver worker stopped' });
      restart();
    };
    return w;
  }

  function restart(): void {
    worker.terminate();
    worker = spawn();
  }

  function cancel(): void {
    if (!pending) return;
    const p = pending;
    pending = null;
    restart();
    p.resolve({ status: 'cancelled' });
  }

  return {
    solve(job, onProgress) {
      cancel();
      const id = nextId++;
      const request: SolveRequest = { type: 'solve', id, ...job, points: job.points.slice() };
      return new Promise<SolveOutcome>((resolve) => {
        pending = { id, resolve, onProgress };
        worker.postMessage(request, [request.points.buffer]);
      });
    },
    cancel,
    get busy() {
      return pending !== null;
    },
  };
}
