/**
 * hodt: optimal first order Delaunay triangulations of terrains.
 *
 *   const hodt = await loadHodt();
 *   using terrain = hodt.terrain(xyz);              // Float64Array x, y, z, ...
 *   const best = terrain.solve('min-local-minima');
 *   best.triangles                                  // Uint32Array for three.js
 *
 * Reference: docs/api.md.
 */
import { describeValue, guard, InputError } from './errors.js';
import { loadModule, type LoadOptions } from './load.js';
import type { MeshData, MeshFormat } from './export/meshData.js';
import type { ObjectiveInfo } from './objectives.js';
import { checkOptionNames } from './options.js';
import { type PointInput, toXyz } from './points.js';
import { type AccessorOptions, type PointOptions, TERRAIN_OPTIONS, type TerrainOptions } from './terrainOptions.js';
import { Terrain } from './terrain.js';
import { stopAfterTrap } from './trap.js';
import type { HodtModule } from './wasm/hodt.mjs';

export { BusyError, CancelledError, HodtError, InputError, InternalError, LimitError } from './errors.js';
export {
  OBJECTIVE_IDS,
  type Method,
  type ObjectiveId,
  type ObjectiveInfo,
  type ObjectiveValues,
  type SolvedBy,
} from './objectives.js';
export * from './terrain.js';
export type * from './explain.js';
export type { LoadOptions } from './load.js';
export type { Accessor, GeoJsonPoints, Point3, PointInput } from './points.js';
export type { ProgressCallback, ProgressInfo, ProgressPhase, SolveOptions } from './solve.js';
export { solveInWorker, type WorkerSolveOptions } from './solveInWorker.js';
export type { AccessorOptions, PointOptions, TerrainOptions } from './terrainOptions.js';

export interface ParsedPoints {
  /** x, y, z per point. */
  points: Float64Array;
  /** 1-based source line of each point. */
  lines: Int32Array;
  /** An ESRI ASCII grid with NODATA cells: its default domain, 3 cell sides
   * (pass it on: `hodt.terrain(points, { maxEdge })`). Absent otherwise. */
  maxEdge?: number;
}

/** The result of running the command line in-process. */
export interface CliResult {
  exitCode: number;
  stdout: string;
  stderr: string;
}

/** What runCli may use besides reading files (the npm bin gives all of it). */
export interface CliIo {
  /** Writes `--output FILE.json`, given its UTF-8 bytes (a copy: keep them);
   * returns an Error (with a Node `code` such as 'ENOENT', or a message) if it
   * cannot. Without it, --output is refused. */
  writeFile?: (path: string, bytes: Uint8Array) => Error | undefined;
  /** Writes `--output FILE.obj|.ply|.geojson|.glb`, typically with hodt/export's
   * exportMesh(format, mesh); returns an Error as writeFile. */
  writeMesh?: (
    path: string,
    format: MeshFormat,
    mesh: Required<Omit<MeshData, 'crs' | 'outside'>> & Pick<MeshData, 'crs' | 'outside'>,
  ) => Error | undefined;
  /** Receives progress text for stderr as it happens (with its own line ends). */
  progress?: (text: string) => void;
  /** Receives the input's notes and warnings for stderr once the input is
   * accepted, before the solve (never for a refused input). Without it they
   * come at the end, in the result's stderr. */
  notes?: (text: string) => void;
  /** Is stderr a terminal: progress then appears after a second, redrawn in place. */
  stderrIsTerminal?: boolean;
}

/** The loaded library (from loadHodt()). It holds no per-terrain state. */
export class Hodt {
  readonly #module: HodtModule;
  /** The 13 objectives with their sense and a one-line summary. */
  readonly objectives: readonly ObjectiveInfo[];

  /** @internal use loadHodt() */
  constructor(module: HodtModule) {
    this.#module = module;
    this.objectives = Object.freeze(module.objectiveTable() as ObjectiveInfo[]);
  }

  /** Builds the Delaunay triangulation of the points and its first order
   * structure. The points are copied; dispose() the terrain when done. */
  terrain(points: PointInput, options?: PointOptions): Terrain;
  /** The same for items of your own, read by the accessors x, y and z. */
  terrain<T>(points: ArrayLike<T>, options: AccessorOptions<T>): Terrain;
  terrain(points: PointInput | ArrayLike<unknown>, options: TerrainOptions<any> = {}): Terrain { // eslint-disable-line @typescript-eslint/no-explicit-any
    checkOptionNames('terrain', options, TERRAIN_OPTIONS);
    const { dedupe = 'error', maxEdge = null, x, y, z } = options ?? {};
    if (dedupe !== 'error' && dedupe !== 'first') {
      throw new InputError(`dedupe is ${describeValue(dedupe)}, expected 'error' or 'first'`);
    }
    const xyz = toXyz(points as PointInput, { x, y, z });
    const terrain = guard(() => new Terrain(this.#module.fromPoints(xyz, dedupe === 'first'), xyz.slice()));
    if (maxEdge !== null) {
      try {
        terrain.maxEdge = maxEdge;
      } catch (e) {
        terrain.dispose();
        throw e;
      }
    }
    return terrain;
  }

  /** A singly-flippable triangulation: your triangles (point indices, three per
   * triangle) plus designated flippable edges (pairs of point indices); every
   * objective applies to it unchanged. */
  fromTriangulation(points: PointInput, triangles: ArrayLike<number>, flippableEdges: ArrayLike<number> = []): Terrain {
    const xyz = toXyz(points);
    return guard(
      () =>
        new Terrain(
          this.#module.fromTriangulation(xyz, Uint32Array.from(triangles), Uint32Array.from(flippableEdges)),
          xyz.slice(),
        ),
    );
  }

  /** Parses a point file: CSV/TSV/whitespace x y z, JSON [[x, y, z], ...] or an
   * ESRI ASCII grid, given as text or as the file's bytes (UTF-8 with or without a
   * byte order mark, or UTF-16); any line endings. Errors name the file, line and
   * value. */
  readPoints(text: string | Uint8Array, name = 'input'): ParsedPoints {
    return guard(() => {
      const r = this.#module.readPoints(text, name);
      return { points: r.xyz, lines: r.lines, ...(r.maxEdge !== undefined ? { maxEdge: r.maxEdge } : {}) };
    });
  }

  /** Bytes of WebAssembly memory reserved so far. Memory grows as terrains need it
   * and never shrinks (dispose() makes it reusable, not smaller): this is the peak. */
  get memoryBytes(): number {
    return this.#module.heapSize();
  }

  /** Runs the `hodt` command line in-process (the npm bin uses it); `read`
   * returns a file's text or bytes, or returns or throws an Error (with a Node
   * `code` such as 'ENOENT', or a message) that the CLI reports: `(path) =>
   * readFileSync(path)` will do. (Besides FILE, the CLI looks for its `.prj`
   * sidecar, and a missing one is no error.) */
  runCli(args: string[], read: (path: string) => string | Uint8Array | Error, io?: CliIo): CliResult {
    const reader = (path: string) => {
      try {
        return read(path);
      } catch (e) {
        return e instanceof Error ? e : new Error(String(e));
      }
    };
    return this.#module.runCli(args, reader, io);
  }
}

let loading: Promise<Hodt> | null = null;
const LOAD_OPTIONS = ['wasmUrl', 'wasmBinary', 'wasmModule'] as const satisfies readonly (keyof LoadOptions)[];

/**
 * Loads the wasm module: once; later calls return the same instance and ignore
 * their options. If loading fails the promise rejects with a HodtError, and the
 * next call tries again. If the module ever traps (a bug in hodt), that call and
 * every later call on it throw InternalError saying so, and the next call loads
 * a new module.
 */
export function loadHodt(options: LoadOptions = {}): Promise<Hodt> {
  try {
    checkOptionNames('loadHodt', options, LOAD_OPTIONS);
  } catch (e) {
    return Promise.reject(e);
  }
  const loaded: Promise<Hodt> = (loading ??= loadModule(options ?? {}).then(
    (m) => {
      // (after a trap, the next loadHodt() loads a fresh module)
      stopAfterTrap(m, () => {
        if (loading === loaded) loading = null;
      });
      return new Hodt(m);
    },
    (e: unknown) => {
      loading = null;
      throw e;
    },
  ));
  return loaded;
}
