import type { Method } from 'hodt';

/** Page options from the URL: ?points=N samples N points instead of 1500, and
 * ?method=brute-force|exact|approx|auto picks the solver (default auto). */
export interface PageParams {
  points: number;
  method: Method;
}

const METHODS: readonly Method[] = ['auto', 'brute-force', 'exact', 'approx'];

export function readParams(search = window.location.search): PageParams {
  const q = new URLSearchParams(search);
  const n = Number(q.get('points'));
  const method = METHODS.find((m) => m === q.get('method')) ?? 'auto';
  return {
    points: Number.isFinite(n) && n >= 4 ? Math.min(Math.round(n), 50_000) : 1500,
    method,
  };
}
