import type { HodtModule, RawTerrain } from './wasm/hodt.mjs';
import { guard, InputError } from './errors.js';
import { type Method, type ObjectiveId, type ObjectiveValues, toValues } from './objectives.js';

/** One byte per flippable quad: 0 keeps the Delaunay diagonal, 1 flips it. */
export type Choice = Uint8Array;

export interface Triangulation {
  /** Vertex indices (input indices), three per triangle, counterclockwise. */
  triangles: Uint32Array;
  /** Twin of each halfedge (halfedge e of triangle floor(e / 3)), -1 on the hull. */
  halfedges: Int32Array;
  /** Hull vertices, counterclockwise. */
  hull: Uint32Array;
}

/** Edge shapes, per halfedge. */
export const EdgeShape = { Convex: 0, Reflex: 1, Flat: 2, Hull: 3 } as const;
/** Vertex classes, per vertex; boundary vertices are not classified. */
export const VertexClass = { Convex: 0, Concave: 1, Flat: 2, Mixed: 3, Boundary: 4 } as const;
/** Local extrema, per vertex (interior vertices only). */
export const Extremum = { None: 0, Minimum: 1, Maximum: 2 } as const;

export interface Measures {
  /** Per halfedge: EdgeShape. */
  edgeShape: Uint8Array;
  /** Per vertex of the triangulation (see Terrain.vertexIndex): VertexClass. */
  vertexClass: Uint8Array;
  /** Per vertex: Extremum. */
  extremum: Uint8Array;
  /** Per vertex: number of neighbours. */
  degree: Uint32Array;
}

export interface SolveOptions {
  /** brute-force (all 2^m choices), exact, approx or auto (default). */
  method?: Method;
  /** Approximation schemes: within a factor (1 - epsilon) of optimal. Default 0.25. */
  epsilon?: number;
  /** Min-max pair objectives: record every threshold the search tested. */
  trace?: boolean;
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
  /** The method that ran (auto reports what it chose). */
  method: string;
  /** Objective value of the returned triangulation. */
  value: number;
  /** Value of the Delaunay (base) triangulation. */
  delaunayValue: number;
  /** True if value is proven optimal. */
  optimal: boolean;
  /** A proven bound on the optimum when not optimal, else null. */
  bound: number | null;
  /** Number of quads not on their Delaunay diagonal. */
  flipped: number;
  timeMs: number;
  /** The choice that gives the triangulation. */
  choice: Choice;
  /** Min-max pair objectives: the two triangles (input indices) attaining the value. */
  critical: { first: Uint32Array; second: Uint32Array; value: number } | null;
  /** The tested thresholds, in order (with `trace: true`). */
  trace: ThresholdStep[];
}

/**
 * A terrain: points, their Delaunay triangulation and its first order structure.
 * It holds wasm memory: call dispose() (or declare it with `using`) when done.
 * Every array it returns is a copy that you own; none points into wasm memory.
 */
export class Terrain implements Disposable {
  #raw: RawTerrain | null;
  #module: HodtModule;

  /** @internal use Hodt.terrain() */
  constructor(module: HodtModule, raw: RawTerrain) {
    this.#module = module;
    this.#raw = raw;
  }

  get #handle(): RawTerrain {
    if (!this.#raw) throw new InputError('this terrain was disposed');
    return this.#raw;
  }

  /** Number of points in the triangulation (after dropping duplicates, if asked). */
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
  /** xyz of the points of the triangulation, in vertex order (see vertexIndex). */
  get points(): Float64Array {
    return this.#handle.points();
  }
  /** Input index of each vertex (the identity unless duplicates were dropped). */
  get vertexIndex(): Uint32Array {
    return this.#handle.inputIndex();
  }
  /** Four input indices per quad: a, b (Delaunay diagonal), c, d (the other). */
  get quads(): Uint32Array {
    return this.#handle.quads();
  }
  /** For each quad, the halfedge of its Delaunay diagonal in `delaunay()`. */
  get quadEdges(): Uint32Array {
    return this.#handle.quadEdges();
  }
  /** For each triangle of any choice's triangulation, its quad or -1 if fixed. */
  get quadOfTriangle(): Int32Array {
    return this.#handle.quadOfTriangle();
  }

  /** The Delaunay triangulation (choice all zeros). */
  delaunay(): Triangulation {
    return guard(() => this.#handle.triangulation(null));
  }
  /** The triangulation of a choice. Triangle slots are stable across choices. */
  triangulation(choice?: Choice): Triangulation {
    return guard(() => this.#handle.triangulation(choice ?? null));
  }
  /** Edge shapes, vertex classes, extrema and degrees of a choice's triangulation. */
  measures(choice?: Choice): Measures {
    return guard(() => this.#handle.measures(choice ?? null));
  }
  /** Values of all 13 objectives for a choice's triangulation. */
  evaluate(choice?: Choice): ObjectiveValues {
    return guard(() => toValues(this.#handle.evaluate(choice ?? null)));
  }
  /** Values of all 13 objectives for the Delaunay triangulation. */
  delaunayValues(): ObjectiveValues {
    return guard(() => toValues(this.#handle.delaunayValues()));
  }
  /** Optimises an objective over the first order triangulations. */
  solve(objective: ObjectiveId, options: SolveOptions = {}): Solution {
    return guard(() => {
      const s = this.#handle.solve(objective, options.method ?? 'auto', options.epsilon ?? 0.25, options.trace ?? false, undefined);
      return { ...s, objective: s.objective as ObjectiveId };
    });
  }
  /** Values of every objective for all 2^m choices (m <= 24): entry
   * [c * 13 + k] is objective k (OBJECTIVE_IDS order) for choice bits c. */
  enumerateAll(): Float64Array {
    return guard(() => this.#handle.enumerateAll());
  }
  /** The CLI's `stats` document. */
  stats(): { points: number; triangles: number; edges: number; flippable: number; hullVertices: number; delaunay: ObjectiveValues } {
    return JSON.parse(this.#handle.statsJson());
  }

  /** Frees the wasm memory. Idempotent; the terrain is unusable afterwards. */
  dispose(): void {
    this.#raw?.delete();
    this.#raw = null;
  }
  [Symbol.dispose](): void {
    this.dispose();
  }
  /** True once disposed. */
  get disposed(): boolean {
    return this.#raw === null;
  }
  /** @internal */
  get module(): HodtModule {
    return this.#module;
  }
}
