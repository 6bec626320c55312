export {};

/** Test hooks the page publishes on window.__hodt (read by tests/e2e). */
export interface HodtTestHooks {
  /** True once the first terrain is drawn. */
  ready: boolean;
  points: number;
  triangles: number;
  quads: number;
  flipped: number;
  /** A solve is running in the worker. */
  solving: boolean;
  /** Number of solves finished (solved, failed or cancelled) so far. */
  solves: number;
  objective: string;
  method: string;
  /** Order k of the triangulations searched (1: first order). */
  order: number;
  /** The 3D view's height exaggeration (the exact factor a link keeps). */
  exaggeration: number | null;
  /** The domain's longest edge (null: none), and how many shown triangles lie
   * outside it (greyed). */
  maxEdge: number | null;
  outsideTriangles: number;
  /** Number of useful order-k edges drawn, or null when they are hidden. */
  usefulEdges: number | null;
  /** The last solution in the CLI's JSON format (parsed), or null. */
  solution: Record<string, unknown> | null;
  /** The shown choice, one '0'/'1' per quad. */
  choice: string;
  selected: number | null;
  /** The message on screen, if any. */
  notice: string | null;
  pointsCsv(): string;
  /** Page (client) coordinates of a data point in the plan view. */
  planToClient(x: number, y: number): { x: number; y: number };
  /** Page (client) coordinates of point i in the 3D view. */
  threeToClient(i: number): { x: number; y: number };
  point(i: number): { x: number; y: number; z: number };
  link(): string | null;
}

/** The teaching views' state (window.__hodtTeach), read by tests/e2e. */
export interface HodtTeachHooks {
  readonly visible: boolean;
  readonly tab: string;
  /** Plain data of one view, by its id (teach/views.ts). */
  view(id: string): Record<string, unknown> | null;
}

declare global {
  interface Window {
    __hodt?: HodtTestHooks;
    __hodtTeach?: HodtTeachHooks;
  }
}
