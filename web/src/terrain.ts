// Terrain implements Disposable: make its declarations compile in projects whose
// lib lacks it (TypeScript >= 5.2 knows this lib; it only adds types).
/// <reference lib="esnext.disposable" preserve="true" />
import { BusyError, describeValue, guard, InputError } from './errors.js';
import { type ObjectiveId, type ObjectiveValues, type SolvedBy, toValues } from './objectives.js';
import type { Explanation } from './explain.js';
import { checkNumber, explainRaw, type SolveOptions, solveRaw } from './solve.js';
import type { RawMeasures, RawSolved, RawTerrain } from './wasm/hodt.mjs';

/** One byte per flippable quad: 0 keeps the Delaunay diagonal, 1 flips it. */
export type Choice = Uint8Array;

export interface Triangulation {
  /** Point indices (into the points you gave), three per triangle,
   * counterclockwise seen from +z: a BufferGeometry index as is. */
  triangles: Uint32Array;
  /** Twin of each halfedge (halfedge e of triangle floor(e / 3)), -1 on the hull. */
  halfedges: Int32Array;
  /** Hull vertices (point indices), counterclockwise. */
  hull: Uint32Array;
}

/** Edge shapes, per halfedge. */
export const EdgeShape = { Convex: 0, Reflex: 1, Flat: 2, Hull: 3 } as const;
/** Vertex classes, per point; boundary vertices are not classified; Dropped marks a
 * duplicate point left out by `dedupe: 'first'`. */
export const VertexClass = { Convex: 0, Concave: 1, Flat: 2, Mixed: 3, Boundary: 4, Dropped: 255 } as const;
/** Local extrema, per point (interior vertices only). */
export const Extremum = { None: 0, Minimum: 1, Maximum: 2 } as const;

export interface Measures {
  /** Per halfedge (as in Triangulation.halfedges): an EdgeShape value. */
  edgeShape: Uint8Array;
  /** Per point (index as in Triangulation.triangles): a VertexClass value. */
  vertexClass: Uint8Array;
  /** Per point: an Extremum value. */
  extremum: Uint8Array;
  /** Per point: number of neighbours (0 for a dropped duplicate); within a
   * domain, those joined by an edge of an inside triangle. */
  degree: Uint32Array;
  /** Per triangle: 1 if inside the domain (every triangle without one). Within
   * a domain an edge needs an inside triangle on each side to have a shape, and
   * a vertex needs all its triangles inside to have a class or be an extremum. */
  inside: Uint8Array;
}

/**
 * The drainage network of one triangulation (docs/api.md, "Drainage"): water at a
 * point runs down the edge to its steepest strictly lower neighbour (slope = height
 * drop over plane length, ties to the smaller index, decided exactly); a point with
 * no lower neighbour drains nowhere: a pit if it is interior, an outlet on the
 * convex hull (or, with maxEdge, touching a triangle outside the domain). Point
 * indices as everywhere; a duplicate dropped by `dedupe: 'first'` is no vertex:
 * downstream and basin -1, accumulation 0.
 */
export interface Drainage {
  /** Per point: the neighbour it drains to, or -1 (a pit or an outlet). */
  downstream: Int32Array;
  /** Per point: the pit or outlet its path down the network ends at. */
  basin: Int32Array;
  /** Per point: how many points drain through it, itself included (a pit's or
   * an outlet's is the size of its basin). */
  accumulation: Uint32Array;
  /** The interior points that drain nowhere, ascending: local minima, and points
   * of a flat (a neighbour of the same height, none lower). */
  pits: Uint32Array;
  /** The points on the hull (or the domain's edge) that drain nowhere, ascending. */
  outlets: Uint32Array;
}

/** One threshold of the bottleneck search (paper, Section 2.1). */
export interface ThresholdStep {
  threshold: number;
  /** Is there a first order triangulation with every pair at most the threshold? */
  satisfiable: boolean;
  /** 2-SAT clauses built (each forced choice counts one). */
  clauses: number;
  /** Quads whose diagonal the eliminations forced. */
  forced: number;
  /** Answered "no" by the eliminations alone (a fixed pair, or a quad with both diagonals over). */
  immediateNo: boolean;
}

export interface Solution {
  objective: ObjectiveId;
  sense: 'min' | 'max';
  /** Order k of the triangulations searched (SolveOptions.order). */
  order: number;
  /** The method that ran: 'auto' reports what it chose; order >= 2 reports
   * 'brute-force', 'exact' (the DP over the regions) or 'heuristic' (local search
   * with a bound). */
  method: SolvedBy;
  /** Objective value of the returned triangulation. */
  value: number;
  /** Value of the Delaunay triangulation, for comparison. */
  delaunayValue: number;
  /** True if `value` is proven optimal. */
  optimal: boolean;
  /** When not optimal: a proven bound on the optimum (the optimum is at least as
   * good as `value` and no better than `bound`); null when optimal or unknown. */
  bound: number | null;
  /** The optimised triangulation: point indices, three per triangle,
   * counterclockwise (order 1: same as `terrain.triangulation(choice).triangles`,
   * in the same triangle slots). */
  triangles: Uint32Array;
  /** Order 1: the choice that gives the triangulation (one byte per quad), for
   * measures(), evaluate() and triangulation(). Order >= 2: empty, since the
   * result need not be a choice of quad diagonals. */
  choice: Choice;
  /** Edges of the result that are not Delaunay edges (order 1: flipped quads). */
  flipped: number;
  /** Time the core spent, in milliseconds. */
  timeMs: number;
  /** Approximations: whether the local search after the scheme improved its result. */
  localSearchImproved: boolean;
  /** What the solver wants you to know (for example why 'auto' fell back to the
   * approximation), or ''. */
  details: string;
  /** Min-max pair objectives: the two triangles (point indices) attaining the value. */
  critical: { first: Uint32Array; second: Uint32Array; value: number } | null;
  /** Order 1, `trace: true`: the tested thresholds, in order; else empty. */
  trace: ThresholdStep[];
  /** Order k >= 2, `trace: true`: the phases of the solve that ran, in order; else empty. */
  phases: PhaseStep[];
}

/** One phase of an order-k solve (`trace: true`): its name, its time, and the answer after it. */
export interface PhaseStep {
  /** The phase, as docs/higher-order.md names it (for example `'the exact DP'`). */
  phase: string;
  ms: number;
  /** The answer's value after it, or null before the first triangulation. */
  value: number | null;
  /** The proven bound after it, or null before the first. */
  bound: number | null;
  /** It found a better triangulation. */
  improved: boolean;
  /** It tightened the bound. */
  tightened: boolean;
  /** The answer is proven optimal after it. */
  proved: boolean;
}

/** The `stats` document of the CLI. */
export interface TerrainStats {
  /** Vertices of the triangulation. */
  points: number;
  triangles: number;
  edges: number;
  /** Flippable quads (m). */
  flippable: number;
  hullVertices: number;
  /** Values of the 13 objectives for the Delaunay triangulation. */
  delaunay: ObjectiveValues;
  /** Pits and outlets of the drainage network of the terrain's own triangulation
   * (see Terrain.drainage). */
  drainage: { pits: number; outlets: number };
  /** With stats(order): the order k and the counts of useful k-OD edges and triangles. */
  order?: number;
  usefulEdges?: number;
  usefulTriangles?: number;
}

/**
 * A terrain: points, their Delaunay triangulation and its first order structure
 * (the m flippable quads). Make one with `hodt.terrain()`.
 *
 * It holds wasm memory that JavaScript's garbage collector does not see: call
 * dispose() when done, or declare it with `using` (TypeScript 5.2+, Node 24+).
 * A terrain that becomes unreachable undisposed is freed after garbage
 * collection too (a FinalizationRegistry safety net), but when is up to the
 * engine: wasm memory can run out first. No array it returns is a view of wasm
 * memory. The arrays that describe the terrain itself (points, vertexIndex,
 * quads, quadEdges, quadOfTriangle) are the same array on every read until the
 * terrain changes, as delaunator's are: read them freely, copy before
 * modifying. Results (solve, measures, triangulation, ...) are new arrays you own.
 * Every point index refers to the points as you gave them.
 *
 * While solve() runs, its progress callback may read the terrain (the solver only
 * reads it too), but changing it (addPoint, movePoint, removePoint), freeing it
 * (dispose) or starting another solve throws BusyError.
 */
// Frees the wasm side of terrains collected without dispose().
const leaked = new FinalizationRegistry<RawTerrain>((raw) => {
  try {
    raw.delete();
  } catch {
    // (a finalizer must not throw: the process would die of it)
  }
});

export class Terrain implements Disposable {
  #raw: RawTerrain | null;
  #input: Float64Array;
  #solving = false;  // a solve() runs: the core holds references into the terrain
  // The structure's arrays, read once per version of the terrain (#edited clears
  // them), and whether `points` has handed #input out (then an edit copies it).
  #cache: { vertexIndex?: Uint32Array; quads?: Uint32Array; quadEdges?: Uint32Array; quadOfTriangle?: Int32Array } = {};
  #inputShared = false;

  /** @internal use Hodt.terrain() or Hodt.fromTriangulation() */
  constructor(raw: RawTerrain, input: Float64Array) {
    this.#raw = raw;
    this.#input = input;
    leaked.register(this, raw, this);
  }

  get #handle(): RawTerrain {
    if (!this.#raw) throw new InputError('this terrain was disposed');
    return this.#raw;
  }
  // The handle for a call that changes or frees the terrain or starts a solve:
  // from a progress callback, it would pull the terrain from under the running
  // solve (memory freed or changed while the core uses it).
  #idle(method: string): RawTerrain {
    if (this.#solving) throw new BusyError(`terrain is busy: ${method} called from inside a progress callback of solve()`);
    return this.#handle;
  }

  /** Number of points you gave. */
  get numInputPoints(): number {
    return this.#handle.numInputPoints();
  }
  /** Number of vertices of the triangulation (fewer than numInputPoints only when
   * duplicates were dropped). */
  get numPoints(): number {
    return this.#handle.numPoints();
  }
  /** Number of flippable quads m: there are 2^m first order triangulations. */
  get numQuads(): number {
    return this.#handle.numQuads();
  }
  /** False for a user triangulation with designated flippable edges. */
  get isDelaunay(): boolean {
    return this.#handle.isDelaunay();
  }
  /** The points as you gave them: x, y, z per point (a BufferGeometry position
   * attribute, after conversion to Float32Array). */
  get points(): Float64Array {
    void this.#handle;
    this.#inputShared = true;
    return this.#input;
  }
  /** Indices of the points that are vertices of the triangulation, ascending (all
   * of them unless duplicates were dropped). */
  get vertexIndex(): Uint32Array {
    return (this.#cache.vertexIndex ??= this.#handle.inputIndex().sort());
  }
  /** Four point indices per quad: a, b (the Delaunay diagonal), c, d (the other). */
  get quads(): Uint32Array {
    return (this.#cache.quads ??= this.#handle.quads());
  }
  /** For each quad, the halfedge of its Delaunay diagonal in `delaunay()`. */
  get quadEdges(): Uint32Array {
    return (this.#cache.quadEdges ??= this.#handle.quadEdges());
  }
  /** For each triangle slot (of any choice's triangulation), its quad or -1 if
   * the triangle is the same in every first order triangulation. */
  get quadOfTriangle(): Int32Array {
    return (this.#cache.quadOfTriangle ??= this.#handle.quadOfTriangle());
  }
  /**
   * The domain, for data with gaps: a triangle with an edge longer than maxEdge
   * (a plane length) is outside and not measured, by every objective, method and
   * order; the triangulations themselves are the same. null: no domain (every
   * triangle is measured). Setting it throws InputError for anything but a
   * positive number or null.
   */
  get maxEdge(): number | null {
    const m = this.#handle.maxEdge();
    return m === Infinity ? null : m;
  }
  set maxEdge(maxEdge: number | null) {
    const raw = this.#idle('maxEdge');
    if (maxEdge !== null && typeof maxEdge !== 'number') {
      throw new InputError(`maxEdge is ${describeValue(maxEdge)}, expected a positive number or null`);
    }
    guard(() => raw.setMaxEdge(maxEdge ?? Infinity));
  }
  /**
   * Warnings about the terrain as it stands: a domain (maxEdge) that leaves at
   * most 1% of the Delaunay triangles inside gives one naming how many are
   * inside and the points' typical spacing (the median Delaunay edge length).
   * Empty otherwise.
   */
  get warnings(): string[] {
    const w = this.#handle.emptyDomainWarning();
    return w ? [w] : [];
  }

  /**
   * Live edits: the triangulation and the flippable quads are updated around the
   * change (a few hundred microseconds on 10k points, where building anew takes
   * milliseconds); afterwards the terrain is the one `hodt.terrain()` would build
   * from the edited points (same triangles and quads, maybe in another order).
   * Indices are point indices as everywhere: addPoint appends and returns the new
   * index, removePoint shifts the later points down by one (like splice). Only for
   * terrains built from points. Throws InputError naming what is wrong (a
   * non-finite value, an index out of range, a position taken by another point,
   * fewer than 3 or only collinear points left) and then changes nothing.
   */
  addPoint(x: number, y: number, z: number): number {
    const raw = this.#idle('addPoint');
    checkCoordinates(this.#input.length / 3, x, y, z);
    const i = guard(() => raw.addPoint(x, y, z));
    const grown = new Float64Array(this.#input.length + 3);
    grown.set(this.#input);
    grown.set([x, y, z], this.#input.length);
    this.#edited(grown);
    return i;
  }
  /** Moves point `index` to (x, y, z); see addPoint. */
  movePoint(index: number, x: number, y: number, z: number): void {
    const raw = this.#idle('movePoint');
    checkIndex(index, this.#input.length / 3);
    checkCoordinates(index, x, y, z);
    guard(() => raw.movePoint(index, x, y, z));
    // In place, unless `points` handed the array out: a read before the edit
    // keeps the points it was read with.
    const moved = this.#inputShared ? this.#input.slice() : this.#input;
    moved[3 * index] = x, moved[3 * index + 1] = y, moved[3 * index + 2] = z;
    this.#edited(moved);
  }
  /** Removes point `index`; later points' indices go down by one. See addPoint.
   * A point dropped as a duplicate (`dedupe: 'first'`) can be removed too: only
   * the indices change. */
  removePoint(index: number): void {
    const raw = this.#idle('removePoint');
    checkIndex(index, this.#input.length / 3);
    guard(() => raw.removePoint(index));
    const shrunk = new Float64Array(this.#input.length - 3);
    shrunk.set(this.#input.subarray(0, 3 * index));
    shrunk.set(this.#input.subarray(3 * index + 3), 3 * index);
    this.#edited(shrunk);
  }

  // The points after an edit: the cached arrays describe the old terrain.
  #edited(input: Float64Array): void {
    this.#input = input;
    this.#inputShared = false;
    this.#cache = {};
  }

  /** The Delaunay triangulation (the choice of all zeros). */
  delaunay(): Triangulation {
    return guard(() => this.#handle.triangulation(null));
  }
  /** The triangulation of a choice (default: Delaunay). Triangle slots are the
   * same for every choice: only the triangles of flipped quads change. */
  triangulation(choice?: Choice): Triangulation {
    return guard(() => this.#handle.triangulation(choice ?? null));
  }
  /** Edge shapes, vertex classes, extrema and degrees of a choice's triangulation. */
  measures(choice?: Choice): Measures {
    return guard(() => this.#byPoint(this.#handle.measures(choice ?? null)));
  }
  /** Measures of any triangulation of these points given as triangles (point
   * indices), such as a higher order result; edgeShape follows their halfedges. */
  measuresOfTriangles(triangles: ArrayLike<number>): Measures {
    const raw = this.#handle;
    const t = triangleIndices(triangles, raw.numInputPoints());
    return guard(() => this.#byPoint(raw.measuresOfTriangles(t)));
  }
  /** Values of all 13 objectives for any triangulation of these points. */
  evaluateTriangles(triangles: ArrayLike<number>): ObjectiveValues {
    const raw = this.#handle;
    const t = triangleIndices(triangles, raw.numInputPoints());
    return guard(() => toValues(raw.evaluateTriangles(t)));
  }
  /**
   * The drainage network of a triangulation of these points: by default the
   * terrain's own (`delaunay()`), else the one given as triangles (point indices,
   * three per triangle, such as `solution.triangles` at any order). Throws
   * InputError naming what is wrong when the triangles are not a triangulation
   * of the points. Linear in the number of points.
   */
  drainage(triangles?: ArrayLike<number>): Drainage {
    const raw = this.#handle;
    const t = triangles === undefined ? null : triangleIndices(triangles, raw.numInputPoints());
    return guard(() => raw.drainage(t));
  }
  // Vertex arrays of the core (internal vertex order) by point index.
  #byPoint(m: RawMeasures): Measures {
    const raw = this.#handle;
    const index = raw.inputIndex();
    const n = raw.numInputPoints();
    return {
      edgeShape: m.edgeShape,
      vertexClass: scatter(new Uint8Array(n).fill(VertexClass.Dropped), m.vertexClass, index),
      extremum: scatter(new Uint8Array(n), m.extremum, index),
      degree: scatter(new Uint32Array(n), m.degree, index),
      inside: m.inside,
    };
  }
  /** Values of all 13 objectives for a choice's triangulation (default: Delaunay). */
  evaluate(choice?: Choice): ObjectiveValues {
    return guard(() => toValues(this.#handle.evaluate(choice ?? null)));
  }
  /** Values of all 13 objectives for the Delaunay triangulation. */
  delaunayValues(): ObjectiveValues {
    return guard(() => toValues(this.#handle.delaunayValues()));
  }
  /**
   * Optimises an objective over the first order triangulations (or those of
   * order k, with `order: k`). Synchronous: it
   * blocks the thread it runs on (run it in a Worker to keep a page responsive).
   * Throws InputError (bad options), LimitError (refused, with the reason) or
   * CancelledError (see SolveOptions.signal and .progress).
   */
  solve(objective: ObjectiveId, options: SolveOptions = {}): Solution {
    return this.#run('solve', (raw) => this.#solution(raw, solveRaw(raw, objective, options)));
  }
  /**
   * The same solve as solve(objective, options), with the structures its solvers
   * built beside the solution (Explanation): the bottleneck search's tests with
   * their clauses and components, Baker's layers and shifts, the exact engine's
   * decomposition, the regions of the order. For teaching and checking; it costs
   * more than solve() (the shifts' triangulations, the regions' counts).
   */
  explain(objective: ObjectiveId, options: Omit<SolveOptions, 'trace'> = {}): Explanation {
    return this.#run('explain', (raw) => {
      const e = explainRaw(raw, objective, options);
      return { ...e, solution: this.#solution(raw, e.solution) };
    });
  }
  // A run of the core that calls back into JS (progress): the terrain is busy meanwhile.
  #run<T>(method: string, run: (raw: RawTerrain) => T): T {
    const raw = this.#idle(method);
    this.#solving = true;
    try {
      return run(raw);
    } finally {
      this.#solving = false;
    }
  }
  #solution(raw: RawTerrain, s: RawSolved): Solution {
    const triangles = s.triangles ?? guard(() => raw.triangulation(s.choice).triangles);
    return {
      objective: s.objective as ObjectiveId,
      sense: s.sense,
      order: s.order,
      method: s.method,
      value: s.value,
      delaunayValue: s.delaunayValue,
      optimal: s.optimal,
      bound: s.bound,
      triangles,
      choice: s.choice,
      flipped: s.flipped,
      timeMs: s.timeMs,
      localSearchImproved: s.localSearchImproved,
      details: s.details,
      critical: s.critical,
      trace: s.trace,
      phases: s.phases,
    };
  }
  /** Values of every objective for all 2^m choices (m <= 24): entry
   * [c * 13 + k] is objective k (OBJECTIVE_IDS order) for the choice whose bit q
   * is quad q's entry. */
  enumerateAll(): Float64Array {
    return guard(() => this.#handle.enumerateAll());
  }
  /** The CLI's `stats` document; with an order k, also the numbers of useful k-OD
   * edges and triangles (like `hodt stats --order K`). */
  stats(order?: number): TerrainStats {
    if (order !== undefined) checkNumber('order', order);
    const raw = this.#handle;
    return guard(() => JSON.parse(raw.statsJson(order ?? 0)) as TerrainStats);
  }
  /** Useful order-k Delaunay edges: pairs of point indices, the edges that appear
   * in some triangulation whose triangles' circumcircles hold at most k points
   * each (order 1: the Delaunay edges plus the quads' other diagonals). */
  usefulEdges(order: number): Uint32Array {
    checkNumber('order', order);
    const raw = this.#handle;
    return guard(() => raw.usefulEdges(order));
  }
  /** Useful order-k Delaunay triangles: triples of point indices, the triangles
   * whose circumcircle holds at most k points and whose three edges are useful
   * order-k edges. */
  usefulTriangles(order: number): Uint32Array {
    checkNumber('order', order);
    const raw = this.#handle;
    return guard(() => raw.usefulTriangles(order));
  }

  /** Frees the wasm memory. Idempotent; any other use afterwards throws InputError. */
  dispose(): void {
    if (this.#raw) {
      this.#idle('dispose').delete();
      leaked.unregister(this);
    }
    this.#raw = null;
    this.#cache = {};
  }
  /** Same as dispose(), for `using terrain = hodt.terrain(points)`. */
  [Symbol.dispose](): void {
    this.dispose();
  }
  /** True once disposed. */
  get disposed(): boolean {
    return this.#raw === null;
  }
}

// embind would truncate or wrap a bad index; name it instead.
function checkIndex(index: unknown, count: number): asserts index is number {
  if (typeof index !== 'number') throw new InputError(`point index is ${describeValue(index)}, expected an integer`);
  if (!Number.isInteger(index) || index < 0 || index >= count)
    throw new InputError(`point ${index} is out of range (${count} points)`);
}

// embind throws an untyped TypeError for a non-number (a BigInt, a string):
// name the coordinate as the core names a NaN one.
function checkCoordinates(point: number, x: unknown, y: unknown, z: unknown): void {
  const xyz = { x, y, z };
  for (const axis of ['x', 'y', 'z'] as const) {
    const v = xyz[axis];
    if (typeof v !== 'number') throw new InputError(`point ${point}: ${axis} is ${describeValue(v)}, expected a finite number`);
  }
}

// Triangles as the core takes them: a Uint32Array as it is (the core names an
// index that is not a vertex), anything else checked here, since the conversion
// would wrap -1 and truncate 2.5 without a word.
function triangleIndices(triangles: ArrayLike<number>, count: number): Uint32Array {
  if (triangles instanceof Uint32Array) return triangles;
  if (triangles === null || typeof triangles !== 'object' || typeof triangles.length !== 'number') {
    throw new InputError(`triangles is ${describeValue(triangles)}, expected point indices, three per triangle`);
  }
  for (let k = 0; k < triangles.length; k++) {
    const v: unknown = triangles[k];
    if (typeof v !== 'number' || !Number.isInteger(v) || v < 0 || v >= count) {
      throw new InputError(`triangles[${k}] is ${describeValue(v)}, expected a point index from 0 to ${count - 1}`);
    }
  }
  return Uint32Array.from(triangles);
}

/** out[index[v]] = values[v]: per-vertex values into point order. */
function scatter<T extends Uint8Array | Uint32Array>(out: T, values: ArrayLike<number>, index: Uint32Array): T {
  for (let v = 0; v < index.length; ++v) out[index[v]!] = values[v]!;
  return out;
}
