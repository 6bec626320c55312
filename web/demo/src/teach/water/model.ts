// The model of the Water view (issue 60): the drainage network of the Delaunay
// triangulation and of an optimum, from the library's terrain.drainage, and what
// the view draws of it: the flow segments with their accumulation, the basin of
// every vertex, the pits and the outlets. The view decides nothing itself: which
// point drains where is the library's answer.
import type { ObjectiveId, Terrain } from 'hodt';
import type { SolveOutcome } from '../../solver/solverClient.ts';
import { BASIN_COLORS, basinSlots } from './waterStyle.js';

/** One triangulation's drainage network, as the view draws it. */
export interface WaterNetwork {
  /** The triangulation (point indices, three per triangle). */
  triangles: Uint32Array;
  /** Flow segments: pairs (from, to) of point indices, one per point that drains somewhere. */
  segments: Uint32Array;
  /** Per segment: the accumulation of its `from` point (points draining through it). */
  accumulation: Uint32Array;
  /** Per point: the pit or outlet it drains to (-1 for a dropped duplicate). */
  basin: Int32Array;
  pits: Uint32Array;
  outlets: Uint32Array;
  /** Basins: one per pit and one per outlet, where water ends. */
  basins: number;
  /** The largest accumulation (for scaling the flow lines' widths). */
  maxAccumulation: number;
}

/** The drainage of a triangulation of the terrain's points (the terrain's own,
 * Delaunay, when `triangles` is omitted). */
export function networkOf(terrain: Terrain, triangles?: Uint32Array): WaterNetwork {
  const d = terrain.drainage(triangles);
  const tris = triangles ?? terrain.delaunay().triangles;
  const n = d.downstream.length;
  let count = 0;
  for (let v = 0; v < n; v++) if (d.downstream[v]! >= 0) count++;
  const segments = new Uint32Array(2 * count), accumulation = new Uint32Array(count);
  let maxAccumulation = 0;
  for (let v = 0, s = 0; v < n; v++) {
    maxAccumulation = Math.max(maxAccumulation, d.accumulation[v]!);
    const w = d.downstream[v]!;
    if (w < 0) continue;
    segments[2 * s] = v;
    segments[2 * s + 1] = w;
    accumulation[s++] = d.accumulation[v]!;
  }
  return { triangles: tris, segments, accumulation, basin: d.basin, pits: d.pits, outlets: d.outlets, basins: d.pits.length + d.outlets.length, maxAccumulation };
}

/** The two triangulations the view compares. */
export type WaterSide = 'delaunay' | 'optimum';
/** What the view shows: both side by side, or one of them (for narrow screens). */
export type WaterLayout = 'both' | WaterSide;

/** The panes a layout shows, left to right. */
export const sidesOf = (layout: WaterLayout): readonly WaterSide[] => (layout === 'both' ? ['delaunay', 'optimum'] : [layout]);

export interface WaterState {
  order: number;
  objective: ObjectiveId;
  delaunay: WaterNetwork;
  /** The optimum's network, once the solver answered. */
  optimum: WaterNetwork | null;
  failure: string | null;
  /** Per point: the colour slot of its Delaunay basin (waterStyle.js). A basin of
   * either network is drawn in the slot of its pit or outlet, so a basin keeps
   * its colour in the optimum and a merged one takes its neighbour's. */
  slots: Int32Array;
}

/** The state while the optimum is being solved (Delaunay's network is at hand). */
export function startWater(terrain: Terrain, order: number, objective: ObjectiveId): WaterState {
  const delaunay = networkOf(terrain);
  return { order, objective, delaunay, optimum: null, failure: null, slots: basinSlots(delaunay.triangles, delaunay.basin, BASIN_COLORS.length) };
}

/** The state with the solver's answer: the drainage of the returned triangles. */
export function withSolution(s: WaterState, o: SolveOutcome, terrain: Terrain): WaterState {
  if (o.status !== 'solved') return { ...s, failure: o.status === 'failed' ? o.message : 'cancelled' };
  return { ...s, optimum: networkOf(terrain, o.solution.triangles) };
}

/** A side's network: the optimum's, once solved. */
export const networkFor = (s: WaterState, side: WaterSide): WaterNetwork | null => (side === 'delaunay' ? s.delaunay : s.optimum);

const plural = (n: number, word: string) => `${n} ${word}${n === 1 ? '' : 's'}`;
const describe = (w: WaterNetwork) => `${plural(w.pits.length, 'pit')}, ${plural(w.basins, 'basin')}`;

/** "Delaunay: P pits, B basins; optimum (order k): P' pits, B' basins". */
export function countsText(s: WaterState): string {
  return `Delaunay: ${sideCounts(s, 'delaunay')}; optimum (order ${s.order}): ${sideCounts(s, 'optimum')}`;
}

/** A pane's counts: "P pits, B basins", or why there are none yet. */
export function sideCounts(s: WaterState, side: WaterSide): string {
  const w = networkFor(s, side);
  return w ? describe(w) : s.failure ? `not solved (${s.failure})` : 'solving…';
}

export function waterHooks(s: WaterState | null, layout: WaterLayout, counts: string, panes: Record<WaterSide, string>): Record<string, unknown> {
  const net = (w: WaterNetwork | null | undefined) => (w ? { pits: w.pits.length, outlets: w.outlets.length, basins: w.basins, segments: w.segments.length / 2 } : null);
  return { order: s?.order ?? null, objective: s?.objective ?? null, layout, delaunay: net(s?.delaunay), optimum: net(s?.optimum), failure: s?.failure ?? null, counts, panes };
}
