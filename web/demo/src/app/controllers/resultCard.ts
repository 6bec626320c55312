// The result card follows the page's solve: running (with Cancel) and its
// progress, then the outcome of that run.
import type { ObjectiveInfo } from 'hodt';
import type { ResultCard } from '../../ui/resultCard.ts';
import type { AppState } from '../appState.ts';
import type { Store } from '../store.ts';

export function connectResultCard(store: Store<AppState>, card: ResultCard, objectives: readonly ObjectiveInfo[], cancel: () => void): void {
  // A newer solve starts with new settings, so the settings are those of the run.
  const objective = (s: AppState) => objectives.find((o) => o.id === s.settings.objective)!;
  store.subscribe(
    (s, p) => {
      if (s.solveRun !== p.solveRun) card.running(objective(s), cancel);
      else if (s.progress && s.progress !== p.progress) card.progress(s.progress);
      const o = s.outcome;
      if (!o || o === p.outcome) return;
      if (o.status === 'solved') card.solved(objective(s), o.solution, s.committed.structure.quads.length / 4, o.explanation?.regions);
      else if (o.status === 'failed') card.failed(objective(s), o.message, s.settings.order);
      else card.cancelled(objective(s));
    },
    ['solveRun', 'progress', 'outcome'],
  );
}
