import type { Analysis } from './analysis.ts';

const CLASS_NAMES = ['convex', 'concave', 'flat', 'mixed', 'on the boundary'];

/** One line about point i for a student: its class, extremum, height and degree. */
export function describeVertex(a: Analysis, i: number): string {
  const cls = CLASS_NAMES[a.vertexClass[i]!] ?? 'unclassified';
  const extremum = a.extremum[i] === 1 ? ', a local minimum ▼' : a.extremum[i] === 2 ? ', a local maximum ▲' : '';
  const z = a.points[3 * i + 2]!;
  return `Point ${i}: ${cls}${extremum}, height ${Number(z.toPrecision(6))}, degree ${a.degree[i]}`;
}
