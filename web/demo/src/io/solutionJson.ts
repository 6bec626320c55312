import type { Solution, Terrain } from 'hodt';

/** A solution in the CLI's `solve` format (README, "CLI"): the same keys in the
 * same order, with the drainage counts of its triangulation on `terrain` (the
 * one it was solved on), plus `critical` when the objective has a critical pair. */
export function solutionToJson(s: Solution, terrain: Terrain): string {
  const doc: Record<string, unknown> = {
    objective: s.objective,
    sense: s.sense,
    method: s.method,
    value: s.value,
    delaunayValue: s.delaunayValue,
    optimal: s.optimal,
    bound: s.bound,
    flipped: s.flipped,
    timeMs: s.timeMs,
  };
  const d = terrain.drainage(s.triangles);
  doc.drainage = { pits: d.pits.length, outlets: d.outlets.length };
  if (s.critical) {
    doc.critical = { first: [...s.critical.first], second: [...s.critical.second], value: s.critical.value };
  }
  return `${cliJson(doc)}\n`;
}

/** JSON with the CLI's spacing: `{"key": value, ...}` and `[a, b]`. */
function cliJson(v: unknown): string {
  if (Array.isArray(v)) return `[${v.map(cliJson).join(', ')}]`;
  if (v !== null && typeof v === 'object') {
    return `{${Object.entries(v).map(([k, x]) => `${JSON.stringify(k)}: ${cliJson(x)}`).join(', ')}}`;
  }
  return JSON.stringify(v);
}
