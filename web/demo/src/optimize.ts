import { HodtError, type Method, type ObjectiveId, type Solution, type Terrain } from 'hodt';

export type OptimizeResult = { ok: true; solution: Solution } | { ok: false; message: string };

/** Runs terrain.solve; a refusal or failure becomes a message rather than a throw. */
export function optimize(terrain: Terrain, id: ObjectiveId, method: Method = 'auto'): OptimizeResult {
  try {
    return { ok: true, solution: terrain.solve(id, { method }) };
  } catch (e) {
    if (e instanceof HodtError) return { ok: false, message: `${e.name}: ${e.message}` };
    return { ok: false, message: e instanceof Error ? e.message : String(e) };
  }
}

/** One line describing a solution for the status bar. */
export function describe(s: Solution): string {
  const fmt = (v: number) => (Number.isInteger(v) ? String(v) : v.toPrecision(4));
  const proof = s.optimal ? 'optimal' : s.bound !== null ? `bound ${fmt(s.bound)}` : 'not proven optimal';
  const flips = `${s.flipped} quad${s.flipped === 1 ? '' : 's'} flipped`;
  return `${s.objective}: ${fmt(s.delaunayValue)} (Delaunay) → ${fmt(s.value)}, ${proof}, ${flips}, ${s.method}, ${Math.round(s.timeMs)} ms`;
}
