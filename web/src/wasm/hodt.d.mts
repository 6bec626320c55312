// Types of the Emscripten glue (hodt.mjs, built from wasm/bindings.cpp). Internal:
// the public API is in ../index.ts.
import type { BakerExplanation, ExactExplanation, RegionExplanation, SearchExplanation } from '../explain.js';
import type { SolvedBy } from '../objectives.js';
import type { ProgressInfo } from '../solve.js';
import type { PhaseStep, ThresholdStep } from '../terrain.js';
export interface RawChoiceResult {
  triangles: Uint32Array;
  halfedges: Int32Array;
  hull: Uint32Array;
}
export interface RawMeasures {
  edgeShape: Uint8Array;
  vertexClass: Uint8Array;
  extremum: Uint8Array;
  degree: Uint32Array;
  inside: Uint8Array;
}
export interface RawDrainage {
  downstream: Int32Array;
  basin: Int32Array;
  accumulation: Uint32Array;
  pits: Uint32Array;
  outlets: Uint32Array;
}
export interface RawSolution {
  objective: string;
  sense: 'min' | 'max';
  method: SolvedBy;
  value: number;
  delaunayValue: number;
  optimal: boolean;
  bound: number | null;
  flipped: number;
  timeMs: number;
  choice: Uint8Array;
  critical: { first: Uint32Array; second: Uint32Array; value: number } | null;
  localSearchImproved: boolean;
  details: string;
  trace: ThresholdStep[];
  phases: PhaseStep[];
}
/** What solve and explain return: order k >= 2 adds the triangles (not a choice of diagonals). */
export type RawSolved = RawSolution & { order: number; triangles?: Uint32Array };
export interface RawExplanation {
  solution: RawSolved;
  search: SearchExplanation | null;
  baker: BakerExplanation | null;
  exact: ExactExplanation | null;
  regions: RegionExplanation | null;
}
export interface RawTerrain {
  numPoints(): number;
  numInputPoints(): number;
  numQuads(): number;
  isDelaunay(): boolean;
  inputIndex(): Uint32Array;
  points(): Float64Array;
  quads(): Uint32Array;
  quadEdges(): Uint32Array;
  quadOfTriangle(): Int32Array;
  maxEdge(): number;
  setMaxEdge(maxEdge: number): void;
  emptyDomainWarning(): string;
  addPoint(x: number, y: number, z: number): number;
  movePoint(i: number, x: number, y: number, z: number): void;
  removePoint(i: number): void;
  triangulation(choice: Uint8Array | null): RawChoiceResult;
  measures(choice: Uint8Array | null): RawMeasures;
  evaluate(choice: Uint8Array | null): Float64Array;
  delaunayValues(): Float64Array;
  evaluateTriangles(triangles: Uint32Array): Float64Array;
  measuresOfTriangles(triangles: Uint32Array): RawMeasures;
  /** null: the terrain's own triangulation. */
  drainage(triangles: Uint32Array | null): RawDrainage;
  /** order >= 2: with the triangles (not a choice of diagonals). */
  solve(
    objective: string,
    method: string,
    epsilon: number,
    trace: boolean,
    order: number,
    progress: ((done: number, total: number, info: ProgressInfo) => boolean | void) | undefined,
  ): RawSolved;
  explain(
    objective: string,
    method: string,
    epsilon: number,
    order: number,
    progress: ((done: number, total: number, info: ProgressInfo) => boolean | void) | undefined,
  ): RawExplanation;
  enumerateAll(): Float64Array;
  statsJson(order: number): string;
  usefulEdges(order: number): Uint32Array;
  usefulTriangles(order: number): Uint32Array;
  delete(): void;
  isDeleted(): boolean;
}
export interface RawObjective {
  id: string;
  sense: 'min' | 'max';
  combine: 'sum' | 'max';
  integral: boolean;
  polynomial: boolean;
  unit: string;
  reference: string;
  summary: string;
}
/** A triangulation to write (hodt/export's MeshData, every attribute given). */
export interface RawMesh {
  points: Float64Array;
  triangles: Uint32Array;
  vertexClass: Uint8Array;
  extremum: Uint8Array;
  nonDelaunay: Uint8Array;
  comment: string;
  /** Within a domain: per triangle, 1 if outside. */
  outside?: Uint8Array;
  /** The input's CRS (EPSG:N or WKT), when known. */
  crs?: string;
}
export interface RawCliIo {
  writeFile?: (path: string, bytes: Uint8Array) => Error | undefined;
  writeMesh?: (path: string, format: 'obj' | 'ply' | 'geojson' | 'glb', mesh: RawMesh) => Error | undefined;
  progress?: (text: string) => void;
  notes?: (text: string) => void;
  stderrIsTerminal?: boolean;
}
export interface HodtModule {
  fromPoints(xyz: Float64Array, dedupe: boolean): RawTerrain;
  fromTriangulation(xyz: Float64Array, triangles: Uint32Array, flippable: Uint32Array): RawTerrain;
  readPoints(text: string | Uint8Array, name: string): { xyz: Float64Array; lines: Int32Array; maxEdge?: number };
  runCli(
    args: string[],
    read: (path: string) => string | Uint8Array | Error,
    io: RawCliIo | undefined,
  ): { exitCode: number; stdout: string; stderr: string };
  objectiveTable(): RawObjective[];
  heapSize(): number;
}
export interface ModuleOptions {
  wasmBinary?: ArrayBuffer | Uint8Array;
  locateFile?: (path: string, prefix: string) => string;
  // Structural: these types must compile where no lib declares WebAssembly.
  instantiateWasm?: (imports: object, receive: (instance: object, module: WebAssembly.Module) => void) => object;
}
// Node-only projects (lib ES2022, @types/node) have no WebAssembly namespace:
// this empty interface gives LoadOptions.wasmModule a name there, and merges
// with the real WebAssembly.Module wherever the DOM or webworker lib declares it.
declare global {
  // eslint-disable-next-line @typescript-eslint/no-namespace
  namespace WebAssembly {
    // eslint-disable-next-line @typescript-eslint/no-empty-object-type
    interface Module {}
  }
}
declare function createHodtModule(options?: ModuleOptions): Promise<HodtModule>;
export default createHodtModule;
