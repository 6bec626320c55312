// terrain.solve() runs on the calling thread until it is done: a timer or a click
// cannot abort its signal meanwhile, because neither can run. solveInWorker runs
// the same solve in a worker (a module Worker in browsers, worker_threads in
// Node) and terminates it when the signal aborts, so the promise rejects at once
// whatever the core is doing.
import { BusyError, CancelledError, HodtError, InputError, InternalError, LimitError } from './errors.js';
import { isNode } from './load.js';
import type { ObjectiveId } from './objectives.js';
import { checkOptionNames } from './options.js';
import { type PointInput, toXyz } from './points.js';
import type { SolveOptions } from './solve.js';
import type { Solution } from './terrain.js';
import { type AccessorOptions, type PointOptions, TERRAIN_OPTIONS } from './terrainOptions.js';
import type { WorkerReply, WorkerRequest } from './workerProtocol.js';

/** SolveOptions, the terrain's options and where the worker finds hodt.wasm. */
export interface WorkerSolveOptions<Options = PointOptions> extends SolveOptions {
  /** How the worker builds the terrain (hodt.terrain's options). Accessors run
   * on the calling thread, before the points are sent. */
  terrain?: Options;
  /** LoadOptions for the worker's loadHodt (default: hodt.wasm next to the JS). */
  wasmUrl?: string | URL;
  wasmModule?: WebAssembly.Module;
}

const OPTIONS = ['method', 'epsilon', 'order', 'trace', 'progress', 'signal', 'terrain', 'wasmUrl', 'wasmModule'] as const;

/** The worker as both kinds are driven: post, receive, stop. */
interface SolverWorker {
  post(message: WorkerRequest, transfer: ArrayBuffer[]): void;
  terminate(): void;
}

async function startWorker(onReply: (reply: WorkerReply) => void, onError: (message: string) => void): Promise<SolverWorker> {
  if (isNode) {
    // The module name is a variable so that bundlers for the browser leave it alone.
    const name = 'node:worker_threads';
    const { Worker } = (await import(/* @vite-ignore */ /* webpackIgnore: true */ name)) as typeof import('node:worker_threads');
    const worker = new Worker(new URL('./solveWorker.js', import.meta.url));
    worker.on('message', onReply);
    worker.on('error', (e: Error) => onError(e.message));
    worker.on('exit', (code: number) => onError(`it exited with code ${code}`));
    return { post: (m, transfer) => worker.postMessage(m, transfer), terminate: () => void worker.terminate() };
  }
  // Written out as bundlers recognise it, so that they bundle the worker too.
  const worker = new Worker(new URL('./solveWorker.js', import.meta.url), { type: 'module', name: 'hodt-solve' });
  worker.onmessage = (event: MessageEvent<WorkerReply>) => onReply(event.data);
  worker.onerror = (event: ErrorEvent) => {
    event.preventDefault();
    onError(event.message || 'it could not start');
  };
  return { post: (m, transfer) => worker.postMessage(m, transfer), terminate: () => worker.terminate() };
}

const ERRORS: Record<string, new (message: string) => HodtError> = {
  InputError,
  BusyError,
  LimitError,
  AbortError: CancelledError,
  InternalError,
  HodtError,
};

/**
 * terrain.solve(objective, options) in a worker of its own, for a solve that may
 * run long: the calling thread stays free, and `signal` (for example
 * `AbortSignal.timeout(ms)`) stops it at any moment by terminating the worker;
 * the promise then rejects with CancelledError (`cause`: the signal's reason).
 * `progress` is called with the worker's progress; returning false cancels the
 * same way. Each call starts a worker, loads hodt.wasm in it and builds the
 * terrain there, so for many short solves use hodt.terrain() and solve().
 * Errors are the same typed errors solve() throws.
 */
export function solveInWorker(points: PointInput, objective: ObjectiveId, options?: WorkerSolveOptions): Promise<Solution>;
/** The same for items of your own, read by the accessors in `options.terrain`. */
export function solveInWorker<T>(
  points: ArrayLike<T>,
  objective: ObjectiveId,
  options: WorkerSolveOptions<AccessorOptions<T>> & { terrain: AccessorOptions<T> },
): Promise<Solution>;
export function solveInWorker(
  points: PointInput | ArrayLike<unknown>,
  objective: ObjectiveId,
  options: WorkerSolveOptions<AccessorOptions<unknown> | PointOptions> = {},
): Promise<Solution> {
  return new Promise<Solution>((resolve, reject) => {
    checkOptionNames('solveInWorker', options, OPTIONS);
    const { terrain = {}, signal, progress, wasmUrl, wasmModule, method, epsilon, order, trace } = options ?? {};
    checkOptionNames('terrain', terrain, TERRAIN_OPTIONS);
    if (progress !== undefined && typeof progress !== 'function') throw new InputError('progress is not a function');
    const { x, y, z, dedupe, maxEdge } = terrain as AccessorOptions<unknown>;
    // A copy of the points that the worker may own (toXyz keeps a Float64Array as is).
    const xyz = toXyz(points as PointInput, { x, y, z });
    const request: WorkerRequest = {
      points: xyz === points ? xyz.slice() : xyz,
      objective,
      terrain: { ...(dedupe !== undefined ? { dedupe } : {}), ...(maxEdge !== undefined ? { maxEdge } : {}) },
      solve: { ...(method !== undefined ? { method } : {}), ...(epsilon !== undefined ? { epsilon } : {}), ...(order !== undefined ? { order } : {}), ...(trace !== undefined ? { trace } : {}) },
      progress: progress !== undefined,
      load: { ...(wasmUrl !== undefined ? { wasmUrl: String(wasmUrl) } : {}), ...(wasmModule !== undefined ? { wasmModule } : {}) },
    };
    if (signal?.aborted) throw new CancelledError('aborted', { cause: signal.reason });

    let worker: SolverWorker | null = null;
    let settled = false;
    const finish = (outcome: () => void) => {
      if (settled) return;
      settled = true;
      signal?.removeEventListener('abort', onAbort);
      worker?.terminate();
      outcome();
    };
    const onAbort = () => finish(() => reject(new CancelledError('aborted', { cause: signal!.reason })));
    signal?.addEventListener('abort', onAbort);
    const onReply = (reply: WorkerReply) => {
      if (reply.kind === 'solved') finish(() => resolve(reply.solution));
      else if (reply.kind === 'failed') finish(() => reject(new (ERRORS[reply.name] ?? HodtError)(reply.message)));
      else if (!settled && progress) {
        try {
          if (progress(reply.done, reply.total, reply.info) === false) finish(() => reject(new CancelledError('cancelled')));
        } catch (error) {
          finish(() => reject(error));
        }
      }
    };
    const onError = (message: string) => finish(() => reject(new HodtError(`the solve worker failed: ${message}`)));
    startWorker(onReply, onError).then(
      (started) => {
        if (settled) return void started.terminate();
        worker = started;
        started.post(request, [request.points.buffer as ArrayBuffer]);
      },
      (e: unknown) => onError(e instanceof Error ? e.message : String(e)),
    );
  });
}
