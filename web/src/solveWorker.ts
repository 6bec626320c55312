// The worker behind solveInWorker (solveInWorker.ts): loads hodt, builds one
// terrain from the points it is sent, solves it and posts the Solution back.
// The same file runs as a browser module Worker and as a Node worker_threads
// Worker; cancelling terminates it, so it never needs to stop on its own.
import { loadHodt } from './index.js';
import type { ProgressInfo } from './solve.js';
import type { WorkerReply, WorkerRequest } from './workerProtocol.js';

interface Port {
  post(message: WorkerReply, transfer?: ArrayBuffer[]): void;
  listen(handler: (message: WorkerRequest) => void): void;
}

// No top-level await: bundlers may emit this worker in a format without it.
function connect(): Promise<Port> {
  const scope = globalThis as unknown as {
    WorkerGlobalScope?: unknown;
    postMessage(message: unknown, transfer: ArrayBuffer[]): void;
    onmessage: ((event: { data: WorkerRequest }) => void) | null;
  };
  if (scope.WorkerGlobalScope !== undefined) {
    return Promise.resolve({
      post: (message, transfer = []) => scope.postMessage(message, transfer),
      listen: (handler) => (scope.onmessage = (event) => handler(event.data)),
    });
  }
  // A Node worker thread. The module name is a variable so that bundlers for the
  // browser leave node:worker_threads alone.
  const name = 'node:worker_threads';
  return (import(/* @vite-ignore */ /* webpackIgnore: true */ name) as Promise<typeof import('node:worker_threads')>).then(
    ({ parentPort }) => ({
      post: (message, transfer = []) => parentPort!.postMessage(message, transfer),
      listen: (handler) => parentPort!.on('message', handler),
    }),
  );
}

void connect().then((port) =>
  port.listen((request) => {
    const { points, objective, terrain: terrainOptions, solve, progress, load } = request;
    loadHodt(load)
      .then((hodt) => {
        const terrain = hodt.terrain(points, terrainOptions);
        let solution;
        try {
          solution = terrain.solve(objective, {
            ...solve,
            ...(progress ? { progress: (done: number, total: number, info: ProgressInfo) => port.post({ kind: 'progress', done, total, info }) } : {}),
          });
        } finally {
          terrain.dispose();
        }
        const transfer = [solution.triangles.buffer, solution.choice.buffer] as ArrayBuffer[];
        port.post({ kind: 'solved', solution }, transfer);
      })
      .catch((e: unknown) => {
        const { name, message } = e instanceof Error ? e : new Error(String(e));
        port.post({ kind: 'failed', name, message });
      });
  }),
);
