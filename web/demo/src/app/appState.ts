// The page's state: what the store (store.ts) holds, and where it starts (the
// link in the address bar, or the default terrain).
import type { Hodt, ProgressInfo, Solution, Terrain } from 'hodt';
import { decodeState, LinkError, type SharedState } from '../share/urlState.ts';
import type { SolveOutcome } from '../solver/solverClient.ts';
import { TERRAINS } from '../terrains/catalog.ts';
import type { SolveSettings } from '../ui/objectivePanel.ts';
import type { TerrainSource } from '../ui/terrainPanel.ts';
import type { Analysis, Structure } from './analysis.ts';
import { startHistory, type History } from './history.ts';
import type { ViewMode } from './settings.ts';
import { buildTerrain } from './terrainBuild.ts';

/** A terrain and its structure (what does not depend on the choice). */
export interface BuiltTerrain {
  terrain: Terrain;
  structure: Structure;
}

/** What undo and redo restore. */
export interface Snapshot {
  points: Float64Array;
  source: TerrainSource | null;
}

export interface AppState {
  /** x, y, z per point, in input order; every edit makes a new array. */
  points: Float64Array;
  /** The built-in generator that made the points, or null (a file, an edit). */
  source: TerrainSource | null;
  settings: SolveSettings;
  view: ViewMode;
  selected: number | null;
  /** The terrain of `points` within settings.maxEdge. The page owns it: it is
   * disposed when an edit replaces it. */
  committed: BuiltTerrain;
  /** While a point is dragged: a terrain with it moved (drawn, not committed). */
  preview: BuiltTerrain | null;
  /** The drag position waiting for the next animation frame (drags are drawn
   * once a frame). */
  dragTarget: { index: number; points: Float64Array } | null;
  history: History<Snapshot>;

  /** Number of the current (or last) solve of the page's worker. */
  solveRun: number;
  solving: boolean;
  /** Solves finished (solved, failed or cancelled) so far. */
  solves: number;
  /** The current run's progress, and its outcome once it is in. */
  progress: ProgressInfo | null;
  outcome: SolveOutcome | null;
  /** The current run's solution (null while it runs or if it failed). */
  solution: Solution | null;

  /** What the 3D and plan views show. */
  shown: Analysis | null;
  /** The next picture frames the views anew (a new terrain). */
  reframe: boolean;
  /** The height exaggeration of the next reframe (from a link); null: automatic. */
  linkedExaggeration: number | null;
  /** The 3D camera has framed the points (until the next reframe). */
  cameraFramed: boolean;
  /** The "useful edges" toggle, and the useful edges of the committed terrain
   * at an order (kept until either changes). */
  showUseful: boolean;
  useful: { terrain: Terrain; order: number; edges: Uint32Array } | null;
}

export const DEFAULT_SOURCE: TerrainSource = { kind: 'volcano', count: 200, seed: 7 };
export const DEFAULT_SETTINGS: SolveSettings = { objective: 'min-mixed-vertices', method: 'auto', epsilon: 0.25, order: 1, maxEdge: null };

export function settingsOf(s: SharedState): SolveSettings {
  return { objective: s.objective, method: s.method, epsilon: s.epsilon, order: s.order, maxEdge: s.maxEdge };
}

/** The state from the URL hash, or the default terrain with a message saying
 * why the hash could not be used. */
export function initialState(hodt: Hodt, hash: string, showUseful: boolean): { state: AppState; message: string | null } {
  let message: string | null = null;
  try {
    const s = decodeState(hash);
    if (s) {
      const built = buildTerrain(hodt, s.points, s.maxEdge);
      if (built.ok) return { state: startingWith(s, built, showUseful), message };
      message = `The link's points are not a valid terrain: ${built.message}. Showing the default terrain instead.`;
    }
  } catch (e) {
    if (!(e instanceof LinkError)) throw e;
    message = `${e.message[0]!.toUpperCase()}${e.message.slice(1)}. Showing the default terrain instead.`;
  }
  const points = TERRAINS[DEFAULT_SOURCE.kind].make(DEFAULT_SOURCE.count, DEFAULT_SOURCE.seed);
  const built = buildTerrain(hodt, points, DEFAULT_SETTINGS.maxEdge);
  if (!built.ok) throw new Error(`the default terrain failed: ${built.message}`);
  const shared: SharedState = { points, ...DEFAULT_SETTINGS, view: 'split', source: DEFAULT_SOURCE, exaggeration: null };
  return { state: startingWith(shared, built, showUseful), message };
}

function startingWith(s: SharedState, built: BuiltTerrain, showUseful: boolean): AppState {
  return {
    points: s.points,
    source: s.source,
    settings: settingsOf(s),
    view: s.view,
    selected: null,
    committed: { terrain: built.terrain, structure: built.structure },
    preview: null,
    dragTarget: null,
    history: startHistory({ points: s.points, source: s.source }),
    solveRun: 0,
    solving: false,
    solves: 0,
    progress: null,
    outcome: null,
    solution: null,
    shown: null,
    reframe: true,
    linkedExaggeration: s.exaggeration,
    cameraFramed: false,
    showUseful,
    useful: null,
  };
}
