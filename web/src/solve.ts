import { CancelledError, describeValue, InputError, toHodtError } from './errors.js';
import type { Method, ObjectiveId } from './objectives.js';
import { checkOptionNames } from './options.js';
import type { RawExplanation, RawSolved, RawTerrain } from './wasm/hodt.mjs';

/** What a solve is doing, by name. 'solving' is work no step of the engine named. */
export type ProgressPhase =
  | 'finding the regions'
  | 'solving exactly'
  | 'approximating'
  | 'searching'
  | 'proving a bound'
  | 'measuring'
  | 'solving';

/** The phase a progress call is about. */
export interface ProgressInfo {
  phase: ProgressPhase;
  /** How far the phase is, 0 to 1 (= done / total); it never goes back within a phase. */
  fraction: number;
  /** The phase knows its size: `fraction` is the share of its work done. Otherwise it
   * only shows that work goes on. */
  sized: boolean;
  /** Estimated seconds the phase still needs: a sized phase after 2 s and 5% of its
   * work; else null. */
  secondsLeft: number | null;
}

/**
 * Called now and then during long runs: at the start of each phase and then at
 * most every few milliseconds, with how far the phase is (`done` out of `total`,
 * never going back within a phase) and `info`, the phase by name. Return false to
 * cancel the run (it then throws CancelledError).
 */
export type ProgressCallback = (done: number, total: number, info: ProgressInfo) => boolean | void;

export interface SolveOptions {
  /** 'auto' (default): exact when the instance fits the memory cap, else the
   * approximation (order 1) or a local search with a certified bound (order k >= 2);
   * 'exact' (refuses, naming the limit, when it does not fit); 'approx';
   * 'brute-force' (the reference: all 2^m choices, m <= 24, at order 1; every k-OD
   * triangulation of at most 30 points at order k). */
  method?: Method;
  /** Approximation schemes, in (0, 1), checked at every order. Default 0.25.
   * max-convex-edges: at least (1 - epsilon) times the optimum; min-mixed-vertices:
   * the guarantee is on the vertices that are not mixed (at least (1 - epsilon)
   * times their most), not on the mixed count. */
  epsilon?: number;
  /** Order k of the Delaunay triangulations to search (every triangle's
   * circumcircle holds at most k points), 1 to 16. Default 1: the 2^m first order
   * triangulations. k >= 2: the regions cut by the fixed edges, each region's k-OD
   * triangulations, and an exact DP over them (`method` 'exact'); when a region has
   * too many triangulations or a table would be too large, a local search from the
   * first order optimum (`method` 'heuristic') with a proven `bound`. */
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
   * if it was aborted before the call or from the progress callback. To stop a
   * solve at any time (a timeout, a Cancel button), use solveInWorker, which runs
   * it in a worker and terminates the worker when the signal aborts.
   */
  signal?: AbortSignal;
}

function aborted(signal: AbortSignal): CancelledError {
  return new CancelledError('aborted', { cause: signal.reason });
}

/** Throws InputError unless value is a number. Only the type: the core checks
 * the value of every option (its range, the method an order has), the same way
 * for the CLI and this API. */
export function checkNumber(name: string, value: unknown): asserts value is number {
  if (typeof value !== 'number') throw new InputError(`${name} is ${describeValue(value)}, expected a number`);
}

const SOLVE_OPTIONS = ['method', 'epsilon', 'order', 'trace', 'progress', 'signal'] as const satisfies readonly (keyof SolveOptions)[];

// The options with their defaults, each checked for its type.
function checkedOptions(objective: unknown, options: SolveOptions | null | undefined) {
  checkOptionNames('solve', options, SOLVE_OPTIONS);
  if (typeof objective !== 'string') throw new InputError(`objective is ${describeValue(objective)}, expected an objective id`);
  const { method = 'auto', epsilon = 0.25, order = 1, trace = false, progress, signal } = options ?? {};
  if (progress !== undefined && typeof progress !== 'function')
    throw new InputError(`progress is ${describeValue(progress)}, expected a function`);
  if (signal !== undefined && (signal === null || typeof signal !== 'object' || typeof signal.aborted !== 'boolean'))
    throw new InputError(`signal is ${describeValue(signal)}, expected an AbortSignal`);
  if (typeof method !== 'string') throw new InputError(`method is ${describeValue(method)}, expected brute-force, exact, approx or auto`);
  checkNumber('epsilon', epsilon);
  checkNumber('order', order);
  return { method, epsilon, order, trace, progress, signal };
}

/** Runs the raw solver with checked options, progress and cancellation. */
export function solveRaw(raw: RawTerrain, objective: ObjectiveId, options: SolveOptions): RawSolved {
  return runChecked(objective, options, (o, tick) => raw.solve(objective, o.method, o.epsilon, o.trace, o.order, tick));
}

/** The same solve, with what its solvers built (Terrain.explain). */
export function explainRaw(raw: RawTerrain, objective: ObjectiveId, options: SolveOptions): RawExplanation {
  return runChecked(objective, options, (o, tick) => raw.explain(objective, o.method, o.epsilon, o.order, tick));
}

type Tick = ((done: number, total: number, info: ProgressInfo) => boolean) | undefined;

function runChecked<T>(objective: ObjectiveId, options: SolveOptions, call: (o: ReturnType<typeof checkedOptions>, tick: Tick) => T): T {
  const checked = checkedOptions(objective, options);
  const { progress, signal } = checked;
  if (signal?.aborted) throw aborted(signal);
  // A JS exception must not unwind through the wasm frames: the callback catches
  // it, cancels the run, and it is rethrown here once the core has cleaned up.
  let thrown: { error: unknown } | null = null;
  const tick =
    progress || signal
      ? (done: number, total: number, info: ProgressInfo): boolean => {
          if (signal?.aborted) return false;
          if (!progress) return true;
          try {
            return progress(done, total, info) !== false;
          } catch (error) {
            thrown = { error };
            return false;
          }
        }
      : undefined;
  try {
    return call(checked, tick);
  } catch (e) {
    if (thrown) throw (thrown as { error: unknown }).error;
    const error = toHodtError(e);
    if (error instanceof CancelledError && signal?.aborted) throw aborted(signal);
    throw error;
  }
}
