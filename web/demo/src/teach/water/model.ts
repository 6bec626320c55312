// The model of the Water view (issue 60): the drainage network of the Delaunay
// triangulation and of an optimum, from the library's terrain.drainage, and what
// the view draws of it: the flow segments with their accumulation, the basin of
// every vertex, the pits and the outlets. The view decides nothing itself: which
// point drains where is the library's answer.
import type { ObjectiveId, Terrain } from 'hodt';
import type { SolveOutcome } from '../../solver/solverClient.ts';

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

/** Which network the canvas shows. */
export type WaterShown = 'delaunay' | 'optimum';

export interface WaterState {
  order: number;
  objective: ObjectiveId;
  delaunay: WaterNetwork;
  /** The optimum's network, once the solver answered. */
  optimum: WaterNetwork | null;
  failure: string | null;
}

/** The state while the optimum is being solved (Delaunay's network is at hand). */
export const startWater = (terrain: Terrain, order: number, objective: ObjectiveId): WaterState => ({ order, objective, delaunay: networkOf(terrain), optimum: null, failure: null });

/** The state with the solver's answer: the drainage of the returned triangles. */
export function withSolution(s: WaterState, o: SolveOutcome, terrain: Terrain): WaterState {
  if (o.status !== 'solved') return { ...s, failure: o.status === 'failed' ? o.message : 'cancelled' };
  return { ...s, optimum: networkOf(terrain, o.solution.triangles) };
}

/** The network to draw: the optimum falls back to Delaunay until it is solved. */
export const shownNetwork = (s: WaterState, shown: WaterShown): WaterNetwork => (shown === 'optimum' && s.optimum) || s.delaunay;

const plural = (n: number, word: string) => `${n} ${word}${n === 1 ? '' : 's'}`;
const describe = (w: WaterNetwork) => `${plural(w.pits.length, 'pit')}, ${plural(w.basins, 'basin')}`;

/** "Delaunay: P pits, B basins; optimum (order k): P' pits, B' basins". */
export function countsText(s: WaterState): string {
  const optimum = s.optimum ? describe(s.optimum) : s.failure ? `not solved (${s.failure})` : 'solving…';
  return `Delaunay: ${describe(s.delaunay)}; optimum (order ${s.order}): ${optimum}`;
}

/** Line width of a flow segment: grows with log(accumulation), 1 for a point
 * that drains only itself, `widest` for the largest flow. */
export function flowWidth(accumulation: number, maxAccumulation: number, widest = 6): number {
  if (maxAccumulation <= 1) return 1;
  return 1 + ((widest - 1) * Math.log(accumulation)) / Math.log(maxAccumulation);
}

/** A basin's colour slot: by its pit or outlet, so that a basin keeps its colour
 * between Delaunay and the optimum and a merged basin takes the colour of the
 * one it joined. */
export const basinSlot = (root: number, slots: number) => (root < 0 ? -1 : (root * 7919) % slots);

export function waterHooks(s: WaterState | null, shown: WaterShown, counts: string): Record<string, unknown> {
  const net = (w: WaterNetwork | null | undefined) => (w ? { pits: w.pits.length, outlets: w.outlets.length, basins: w.basins, segments: w.segments.length / 2 } : null);
  return { order: s?.order ?? null, objective: s?.objective ?? null, shown, delaunay: net(s?.delaunay), optimum: net(s?.optimum), failure: s?.failure ?? null, counts };
}
