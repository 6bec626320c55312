import { CancelledError, InputError, toHodtError } from './errors.js';
import type { Method, ObjectiveId } from './objectives.js';
import type { RawSolution, RawTerrain } from './wasm/hodt.mjs';

/**
 * Called now and then during long runs with the work `done` out of `total` in the
 * current phase (phases restart the count: it is not monotone over a whole run).
 * Return false to cancel the run (it then throws CancelledError).
 */
export type ProgressCallback = (done: number, total: number) => boolean | void;

export interface SolveOptions {
  /** 'auto' (default): exact when the instance fits the memory cap, else the
   * approximation; 'exact'; 'approx'; 'brute-force' (all 2^m choices, m <= 24). */
  method?: Method;
  /** Approximation schemes: a value within a factor (1 - epsilon) of the optimum,
   * in (0, 1). Default 0.25. */
  epsilon?: number;
  /** Order k of the Delaunay triangulations to search: only 1 is supported (the
   * default); any other value throws InputError. */
  order?: number;
  /** Min-max pair objectives: record every threshold the search tested in
   * `Solution.trace`. */
  trace?: boolean;
  /** See ProgressCallback. */
  progress?: ProgressCallback;
  /**
   * Cancels the run: checked before it starts and at every progress step, then it
   * throws CancelledError with the signal's reason as `cause`. solve() is
   * synchronous, so a signal aborted by a timer or an event can only take effect
   * if it was aborted before the call or from the progress callback; to keep a page
   * responsive and stop at any time, run hodt in a Web Worker.
   */
  signal?: AbortSignal;
}

function aborted(signal: AbortSignal): CancelledError {
  return new CancelledError('aborted', { cause: signal.reason });
}

/** Throws InputError unless order is a positive integer. */
export function checkOrder(order: unknown): asserts order is number {
  if (typeof order !== 'number' || !Number.isInteger(order) || order < 1) {
    throw new InputError(`order is ${String(order)}, expected a positive integer`);
  }
}

function checkOptions(objective: unknown, options: SolveOptions): void {
  if (typeof objective !== 'string') throw new InputError(`objective is ${String(objective)}, expected an objective id`);
  const { method = 'auto', epsilon = 0.25, order = 1 } = options;
  if (typeof method !== 'string') throw new InputError(`method is ${String(method)}, expected brute-force, exact, approx or auto`);
  if (typeof epsilon !== 'number') throw new InputError(`epsilon is ${String(epsilon)}, expected a number in (0, 1)`);
  checkOrder(order);
  if (order !== 1) {
    throw new InputError(`order ${order} is not supported: hodt optimises first order Delaunay triangulations only (order: 1)`);
  }
}

/** Runs the raw solver with checked options, progress and cancellation. */
export function solveRaw(raw: RawTerrain, objective: ObjectiveId, options: SolveOptions): RawSolution {
  checkOptions(objective, options);
  const { method = 'auto', epsilon = 0.25, trace = false, progress, signal } = options;
  if (signal?.aborted) throw aborted(signal);
  // A JS exception must not unwind through the wasm frames: the callback catches
  // it, cancels the run, and it is rethrown here once the core has cleaned up.
  let thrown: { error: unknown } | null = null;
  const tick =
    progress || signal
      ? (done: number, total: number): boolean => {
          if (signal?.aborted) return false;
          if (!progress) return true;
          try {
            return progress(done, total) !== false;
          } catch (error) {
            thrown = { error };
            return false;
          }
        }
      : undefined;
  try {
    return raw.solve(objective, method, epsilon, trace, tick);
  } catch (e) {
    if (thrown) throw (thrown as { error: unknown }).error;
    const error = toHodtError(e);
    if (error instanceof CancelledError && signal?.aborted) throw aborted(signal);
    throw error;
  }
}
