/**
 * hodt: optimal first order Delaunay triangulations of terrains.
 *
 *   const hodt = await loadHodt();
 *   using terrain = hodt.terrain(xyz);           // Float64Array x, y, z, ...
 *   const best = terrain.solve('min-local-minima');
 *   terrain.triangulation(best.choice).triangles // Uint32Array for three.js
 */
import { guard, InputError } from './errors.js';
import { loadModule, type LoadOptions } from './load.js';
import { OBJECTIVE_IDS, type ObjectiveInfo } from './objectives.js';
import { Terrain } from './terrain.js';
import type { HodtModule } from './wasm/hodt.mjs';

export * from './errors.js';
export * from './objectives.js';
export * from './terrain.js';
export type { LoadOptions } from './load.js';

export type PointInput = Float64Array | ArrayLike<number> | ReadonlyArray<{ x: number; y: number; z: number }>;

export interface TerrainOptions {
  /** What to do with two points at the same (x, y): throw (default) or keep the first. */
  dedupe?: 'error' | 'first';
}

export interface ParsedPoints {
  /** x, y, z per point. */
  points: Float64Array;
  /** 1-based source line of each point. */
  lines: Int32Array;
}

/** The loaded library. Create it once with loadHodt(); it holds no per-terrain state. */
export class Hodt {
  readonly #module: HodtModule;
  /** The 13 objectives with their sense and a one-line summary. */
  readonly objectives: readonly ObjectiveInfo[];

  /** @internal use loadHodt() */
  constructor(module: HodtModule) {
    this.#module = module;
    this.objectives = module.objectiveTable() as ObjectiveInfo[];
  }

  /** Builds the Delaunay triangulation and first order structure of points. */
  terrain(points: PointInput, options: TerrainOptions = {}): Terrain {
    const xyz = toXyz(points);
    return guard(() => new Terrain(this.#module, this.#module.fromPoints(xyz, options.dedupe === 'first')));
  }

  /** A singly-flippable triangulation: your triangles plus designated flippable
   * edges (pairs of point indices); every objective applies to it unchanged. */
  fromTriangulation(points: PointInput, triangles: ArrayLike<number>, flippableEdges: ArrayLike<number> = []): Terrain {
    const xyz = toXyz(points);
    return guard(
      () =>
        new Terrain(
          this.#module,
          this.#module.fromTriangulation(xyz, Uint32Array.from(triangles), Uint32Array.from(flippableEdges)),
        ),
    );
  }

  /** Parses a point file (CSV/TSV/whitespace, JSON, ESRI ASCII grid). Errors name
   * the file, line and value. */
  readPoints(text: string, name = 'input'): ParsedPoints {
    return guard(() => {
      const r = this.#module.readPoints(text, name);
      return { points: r.xyz, lines: r.lines };
    });
  }

  /** Runs the `hodt` command line in-process (used by the npm bin). */
  runCli(args: string[], read: (path: string) => string | Error) {
    return this.#module.runCli(args, read);
  }
}

function toXyz(points: PointInput): Float64Array {
  if (points instanceof Float64Array) return points;
  const first = (points as ArrayLike<unknown>)[0];
  if (first !== null && typeof first === 'object') {
    const list = points as ReadonlyArray<{ x: number; y: number; z: number }>;
    const xyz = new Float64Array(list.length * 3);
    list.forEach((p, i) => {
      if (p === null || typeof p !== 'object') throw new InputError(`point ${i}: expected {x, y, z}`);
      xyz[3 * i] = Number(p.x);
      xyz[3 * i + 1] = Number(p.y);
      xyz[3 * i + 2] = Number(p.z);
    });
    return xyz;
  }
  return Float64Array.from(points as ArrayLike<number>);
}

let loading: Promise<Hodt> | null = null;

/** Loads the wasm module (once; later calls return the same instance). */
export function loadHodt(options: LoadOptions = {}): Promise<Hodt> {
  loading ??= loadModule(options).then((m) => new Hodt(m));
  return loading;
}

export { OBJECTIVE_IDS };
