import type { Explanation, Method, ObjectiveId, ProgressInfo, Solution } from 'hodt';

/** Messages between the page and the solver worker (solver/worker.ts). */
export interface SolveRequest {
  type: 'solve';
  id: number;
  /** x, y, z per point, in input order: the worker builds the same terrain. */
  points: Float64Array;
  objective: ObjectiveId;
  method: Method;
  epsilon: number;
  /** Order k (1: first order; k >= 2 leaves the method to the library). */
  order: number;
  /** The domain (Terrain.maxEdge); absent or null: none. */
  maxEdge?: number | null;
  /** Record the thresholds of a min-max search (Solution.trace). */
  trace?: boolean;
  /** Solve through terrain.explain: the reply carries what the solvers built. */
  explain?: boolean;
}

export type WorkerReply =
  /** How far the solve is: the library's progress (its phase, a fraction that never
   * goes back within it, and the time left where the phase knows its size). */
  | { type: 'progress'; id: number; info: ProgressInfo }
  | { type: 'solved'; id: number; solution: Solution; explanation?: Explanation }
  | { type: 'failed'; id: number; name: string; message: string };
