// The model of the Order k view (the paper's Section 4.3): the library's
// explanation of a solve at order k (useful and fixed edges, the regions with
// their numbers of k-OD triangulations, the optimum) on the page's terrain, the
// pits of the optimum against Delaunay's, and the value at every order seen.
// The view decides nothing itself.
import { Extremum, type Explanation, type Measures, type ObjectiveId, type Solution, type Terrain } from 'hodt';
import { countRegions, describeRegions } from '../../app/regionCount.ts';
import type { SolveOutcome } from '../../solver/solverClient.ts';

export interface OrderState {
  order: number;
  objective: ObjectiveId;
  explanation: Explanation | null;
  failure: string | null;
  /** Local minima of the optimum and of Delaunay (point indices), from the library's measures. */
  minima: number[];
  delaunayMinima: number[];
}

/** The value found at one order (the view's table). */
export interface OrderValue {
  value: number;
  optimal: boolean;
  bound: number | null;
  delaunay: number;
}

export const startSolve = (order: number, objective: ObjectiveId): OrderState => ({ order, objective, explanation: null, failure: null, minima: [], delaunayMinima: [] });

/** The local minima (point indices) the library's measures mark. */
export function minimaOf(m: Measures): number[] {
  const out: number[] = [];
  m.extremum.forEach((x, v) => x === Extremum.Minimum && out.push(v));
  return out;
}

/** The state with the library's answer (the terrain measures the pits). */
export function withOutcome(s: OrderState, o: SolveOutcome, terrain: Terrain): OrderState {
  if (o.status !== 'solved' || !o.explanation) return { ...s, failure: o.status === 'failed' ? o.message : 'cancelled' };
  const e = o.explanation;
  return { ...s, explanation: e, minima: minimaOf(terrain.measuresOfTriangles(e.solution.triangles)), delaunayMinima: minimaOf(terrain.measures()) };
}

export const valueOf = (sol: Solution): OrderValue => ({ value: sol.value, optimal: sol.optimal, bound: sol.bound, delaunay: sol.delaunayValue });

/** The table's rows: every order seen, in increasing order. */
export const valueRows = (values: ReadonlyMap<number, OrderValue>) => [...values.entries()].sort((a, b) => a[0] - b[0]);

export function captionText(s: OrderState): string {
  const r = s.explanation?.regions ?? null;
  return r ? `Order ${s.order}: ${describeRegions(countRegions(r))}` : `Order ${s.order}`;
}

/** The optimum's edges (pairs of point indices, each once per triangle side)
 * split into those Delaunay has and those it does not. */
export function splitByDelaunay(delaunay: Uint32Array, triangles: Uint32Array): { kept: number[]; changed: number[] } {
  const edges = new Set<number>();
  const key = (u: number, v: number) => (u < v ? u * 0x200000 + v : v * 0x200000 + u);
  for (let t = 0; t < delaunay.length; t += 3) for (let j = 0; j < 3; j++) edges.add(key(delaunay[t + j]!, delaunay[t + ((j + 1) % 3)]!));
  const kept: number[] = [], changed: number[] = [];
  for (let t = 0; t < triangles.length; t += 3) {
    for (let j = 0; j < 3; j++) {
      const u = triangles[t + j]!, v = triangles[t + ((j + 1) % 3)]!;
      (edges.has(key(u, v)) ? kept : changed).push(u, v);
    }
  }
  return { kept, changed };
}

/** Delaunay's pits that the optimum no longer has. */
export const pitsGone = (s: OrderState) => {
  const now = new Set(s.minima);
  return s.delaunayMinima.filter((v) => !now.has(v));
};

export function orderHooks(s: OrderState | null, caption: string | null): Record<string, unknown> {
  const r = s?.explanation?.regions ?? null;
  return {
    order: s?.order ?? null,
    objective: s?.objective ?? null,
    value: s?.explanation?.solution.value ?? null,
    optimal: s?.explanation?.solution.optimal ?? null,
    regions: r ? r.triangulations.length : null,
    withChoice: r ? countRegions(r).withChoice : null,
    caption,
    useful: r ? r.useful.length / 2 : null,
    fixed: r ? r.fixed.length / 2 : null,
    minima: s?.minima.length ?? null,
    failure: s?.failure ?? null,
  };
}
