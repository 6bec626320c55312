// Solving: a new committed terrain or new settings start a solve of the
// page's worker; its progress, outcome and solution go into the store, and so
// does the picture of the result (unless a point is being dragged).
import type { SolverClient, SolveOutcome } from '../../solver/solverClient.ts';
import type { AppState } from '../appState.ts';
import { choicePicture, solutionPicture } from '../picture.ts';
import type { Store } from '../store.ts';

/** How long an edit waits for its solution before drawing Delaunay meanwhile. */
const SOLUTION_GRACE_MS = 150;

export interface Solving {
  /** Solves the committed terrain in the current settings. With keepDisplay
   * (same points, other settings) the old picture stays until the answer;
   * otherwise Delaunay is drawn if the answer takes a moment. */
  solve(keepDisplay: boolean): void;
  cancel(): void;
}

export function createSolving(store: Store<AppState>, solver: SolverClient): Solving {
  function solve(keepDisplay: boolean): void {
    const start = store.get();
    const run = start.solveRun + 1;
    store.update({ solveRun: run, solving: true, progress: null, outcome: null, solution: null });
    const current = () => store.get().solveRun === run;
    const fallback = keepDisplay
      ? 0
      : window.setTimeout(() => {
          const s = store.get();
          if (current() && !s.preview) store.update({ shown: choicePicture(s, null) });
        }, start.reframe ? 0 : SOLUTION_GRACE_MS);
    const { settings, points } = start;
    // At order k the explanation brings the regions, counted as the Teach view counts them.
    void solver.solve({ points, ...settings, explain: settings.order > 1 }, (info) => current() && store.update({ progress: info })).then((reply) => {
      if (!current()) return; // superseded by a newer edit
      clearTimeout(fallback);
      const s = store.get();
      const quads = s.committed.structure.quads.length / 4;
      let outcome: SolveOutcome = reply;
      if (outcome.status === 'solved' && outcome.solution.order === 1 && outcome.solution.choice.length !== quads) {
        outcome = { status: 'failed', name: 'InternalError', message: 'the worker found a different set of quads' };
      }
      const solution = outcome.status === 'solved' ? outcome.solution : null;
      // While a point is dragged the preview stays; dropping it re-solves.
      const shown = s.preview ? s.shown : solution ? solutionPicture(s, solution) : choicePicture(s, null);
      store.update({ solving: false, solves: s.solves + 1, outcome, solution, shown });
    });
  }

  // Settings are replaced only when asked for (the panel, a teaching view), so
  // new settings re-solve even when they equal the old ones.
  store.subscribe((s, p) => solve(s.committed === p.committed), ['committed', 'settings']);

  return { solve, cancel: () => solver.cancel() };
}
