import type { Explanation, Method, ObjectiveId, Solution } from 'hodt';

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
  /** Work done out of total in the current phase (phases restart the count). */
  | { type: 'progress'; id: number; done: number; total: number }
  | { type: 'solved'; id: number; solution: Solution; explanation?: Explanation }
  | { type: 'failed'; id: number; name: string; message: string };
