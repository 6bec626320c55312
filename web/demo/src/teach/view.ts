// What a teaching view is to the Teach tab: a spec (id, tab label, and how to
// make it), and the view it makes (its pane, told when it is shown or hidden and
// when the page's terrain or settings change). Each view lives in its folder as
// model.ts (its state and logic, no DOM), draw.ts (the canvas) and controls.ts
// (the pane's DOM, the events, and the spec); views.ts lists them.
import type { Hodt, ObjectiveId, Terrain } from 'hodt';
import type { SolveJob, SolveOutcome, SolverClient } from '../solver/solverClient.ts';
import type { SolveSettings } from '../ui/objectivePanel.ts';
import type { TerrainSource } from '../ui/terrainPanel.ts';

/** What the teaching views may use of the page. */
export interface TeachContext {
  hodt: Hodt;
  /** The page's committed terrain (owned by the page: never dispose it). */
  terrain(): Terrain;
  points(): Float64Array;
  settings(): SolveSettings;
  /** Replaces the page's points (undoable, like an import) and optionally picks
   * an objective; `source`: the built-in generator that made them (for the
   * terrain controls and the link). */
  load(points: Float64Array, label: string, objective?: ObjectiveId, source?: TerrainSource): void;
  /** Switches the page to its 3D and plan views. */
  showViews(): void;
  /** Sets the sidebar's objective or epsilon (a view's selector changed): the
   * page re-solves and every view hears changed(). */
  choose(change: { objective?: ObjectiveId; epsilon?: number }): void;
  /** The teaching views' own solver worker (the page's keeps running). */
  solver: SolverClient;
}

export interface TeachView {
  readonly root: HTMLElement;
  /** Shown: bring the view up to date. */
  activate(): void;
  deactivate(): void;
  /** The page's terrain or settings changed. */
  changed(): void;
  /** Plain data for tests/e2e (window.__hodtTeach). */
  hooks(): Record<string, unknown>;
}

/** A tab of the Teach tab. */
export interface TeachViewSpec<Id extends string = string> {
  readonly id: Id;
  readonly label: string;
  create(ctx: TeachContext): TeachView;
}

export const teachView = <const Id extends string>(spec: TeachViewSpec<Id>): TeachViewSpec<Id> => spec;

/**
 * The life of a view computed from the page's terrain and settings: it
 * recomputes only while shown, so a change while it is hidden only marks it
 * stale, and showing it brings it up to date. `follow` copies the sidebar's
 * settings into the view's own controls (on show and on every change), `refresh`
 * recomputes, `changed` runs on a change before it (e.g. to drop a pending
 * answer). The view's `canvas` is redrawn once it is shown (a hidden pane has
 * no size to draw at) and its step `player` stops when it is hidden.
 */
export function pageView(o: {
  root: HTMLElement;
  refresh(): void;
  follow?(): void;
  changed?(): void;
  canvas?: { redraw(): void };
  player?: { stop(): void };
  hooks(): Record<string, unknown>;
}): TeachView & {
  /** The view's own control changed: recompute (now, if shown). `during` runs
   * first (e.g. telling the page, which may recompute the view already). */
  invalidate(during?: () => void): void;
} {
  let active = false;
  let stale = true;
  const run = () => {
    if (!active || !stale) return;
    stale = false;
    o.refresh();
  };
  const invalidate = (during?: () => void) => {
    stale = true;
    during?.();
    run();
  };
  return {
    root: o.root,
    activate() {
      active = true;
      o.follow?.();
      run();
      o.canvas?.redraw();
    },
    deactivate() {
      active = false;
      o.player?.stop();
    },
    changed() {
      o.follow?.();
      o.changed?.();
      invalidate();
    },
    invalidate,
    hooks: o.hooks,
  };
}

/** Solves in the teaching views' worker and hands on only the latest answer: a
 * newer solve, or drop() (the page changed), discards one still running. */
export function latestSolve(solver: SolverClient): { solve(job: SolveJob, then: (o: SolveOutcome) => void): void; drop(): void } {
  let token = 0;
  return {
    solve(job, then) {
      const my = ++token;
      void solver.solve(job).then((o) => my === token && then(o));
    },
    drop: () => void token++,
  };
}
