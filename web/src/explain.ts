// What the solvers really built, as plain data (Terrain.explain): the structures a
// teaching view draws and a test can check, recorded by the core while it solves.
// Quads are indices into terrain.quads; the literal "quad q takes state x" is
// 2 q + x (0: its Delaunay diagonal, 1: flipped); vertices are point indices.
import type { Solution } from './terrain.js';

/** One test of the bottleneck search (paper, Section 2.1): is there a first order
 * triangulation with every pair of triangles at most `threshold`? */
export interface ThresholdTest {
  threshold: number;
  satisfiable: boolean;
  /** Answered "no" before any clause: the floor is over the threshold, or a quad
   * (`blocked`) has both diagonals over it. */
  immediateNo: boolean;
  /** (quad, state it must take) pairs: the quads whose other diagonal is over. */
  forced: Uint32Array;
  /** The quad with both diagonals over the threshold (the test stops at it). */
  blocked: Uint32Array;
  /** (literal, literal) pairs, at least one of each holds; a forced quad's clause
   * is a unit clause (a, a). */
  clauses: Uint32Array;
  /** Per literal: its strongly connected component in the implication graph
   * (Tarjan's numbering, a reverse topological order); -1 in no clause. */
  component: Int32Array;
  /** Quads whose two literals share a component: why the answer is no. */
  conflicts: Uint32Array;
  /** When satisfiable: the state of every quad in the 2-SAT solution; else empty. */
  assignment: Uint8Array;
}

/** The min-max objectives at order 1: the binary search over candidate values
 * (the lowest first: on rasters it is often the optimum). */
export interface SearchExplanation {
  /** The largest value no choice avoids (pairs of fixed triangles). */
  floor: number;
  /** The values that can be the optimum, ascending: a lower bound first, the
   * Delaunay value last. */
  candidates: Float64Array;
  /** Each threshold tested, in order. */
  tests: ThresholdTest[];
}

/** One shift of Baker's scheme, in the objective's units. */
export interface BakerShiftExplanation {
  shift: number;
  /** The optimum of what this shift keeps (the terms its cuts drop at their worst). */
  relaxed: number;
  /** The objective of the triangulation that optimum gives. */
  value: number;
  /** With every dropped term at its best: the optimum is no better than this. */
  bound: number;
  /** Terms the cuts dropped. */
  dropped: number;
  /** The shift's triangulation, a state per quad. */
  choice: Uint8Array;
}

/** Baker's shifting (paper, Section 4). */
export interface BakerExplanation {
  /** Layers per period, ceil(span / epsilon). */
  lambda: number;
  /** Widest tree decomposition of a thick layer. */
  width: number;
  /** Per quad: its layer (peeling depth from the hull). */
  layer: Uint32Array;
  shifts: BakerShiftExplanation[];
}

/** The exact engine: a DP over a tree decomposition of the quads. */
export interface ExactExplanation {
  /** Largest bag size - 1. */
  width: number;
  numComponents: number;
  /** Elimination order of the quads. */
  order: Uint32Array;
  /** Per quad: its independent component. */
  component: Uint32Array;
}

/** Order k (paper, Section 4.3): useful edges, the fixed ones (in every k-OD
 * triangulation) and the regions they cut the hull into. */
export interface RegionExplanation {
  order: number;
  /** Useful k-OD edges, (u, v) pairs. */
  useful: Uint32Array;
  /** Useful edges that no other crosses (hull edges included), (u, v) pairs. */
  fixed: Uint32Array;
  /** The Delaunay triangles, three point indices each. */
  triangles: Uint32Array;
  /** Per Delaunay triangle: its region. */
  regionOfTriangle: Int32Array;
  /** Per region: its k-OD triangulations, counted up to a budget (unfinished:
   * at least 2, for every region of two or more triangles has a choice). */
  triangulations: Uint32Array;
  /** Per region: 1 if that count is exact, 0 if there are more. */
  complete: Uint8Array;
}

export interface Explanation {
  /** The same solution solve() returns with these options. */
  solution: Solution;
  /** Min-max pair objectives at order 1. */
  search: SearchExplanation | null;
  /** Baker's scheme, when it ran (max-convex-edges, min-mixed-vertices, order 1). */
  baker: BakerExplanation | null;
  /** The exact engine, when it ran at order 1. */
  exact: ExactExplanation | null;
  /** The regions of the order (at order 1: the flippable quads); null for a
   * terrain built from a given triangulation. */
  regions: RegionExplanation | null;
}
