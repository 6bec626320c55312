// Messages between solveInWorker and its worker (solveWorker.ts): plain data that
// structured cloning copies the same way to a browser Worker and a Node one.
import type { ObjectiveId } from './objectives.js';
import type { ProgressInfo, SolveOptions } from './solve.js';
import type { Solution } from './terrain.js';

export interface WorkerRequest {
  /** x, y, z per point (accessors already applied on the caller's thread). */
  points: Float64Array;
  objective: ObjectiveId;
  terrain: { dedupe?: 'error' | 'first'; maxEdge?: number | null };
  solve: Pick<SolveOptions, 'method' | 'epsilon' | 'order' | 'trace'>;
  /** Post progress messages (the caller gave a progress callback). */
  progress: boolean;
  /** LoadOptions for the worker's loadHodt (a URL as its string). */
  load: { wasmUrl?: string; wasmModule?: WebAssembly.Module };
}

export type WorkerReply =
  | { kind: 'progress'; done: number; total: number; info: ProgressInfo }
  | { kind: 'solved'; solution: Solution }
  | { kind: 'failed'; name: string; message: string };
