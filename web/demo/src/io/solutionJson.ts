import type { Solution } from 'hodt';

/** A solution in the CLI's `solve` format (README, "CLI"): the same keys in the
 * same order, plus `critical` when the objective has a critical pair. */
export function solutionToJson(s: Solution): string {
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
