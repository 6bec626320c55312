// The sidebar's objective, method, epsilon, order and domain: what the panel
// sets goes into the store, and settings set elsewhere (a link, an import, a
// teaching view) show in the panel. A new domain keeps the points and their
// quads; only the values change.
import type { ObjectivePanel } from '../../ui/objectivePanel.ts';
import { readStructure } from '../analysis.ts';
import type { AppState } from '../appState.ts';
import type { Store } from '../store.ts';

export function connectSolveSettings(store: Store<AppState>, panel: ObjectivePanel): void {
  panel.set(store.get().settings);
  panel.onChange((settings) => {
    const s = store.get();
    if (settings.maxEdge === s.settings.maxEdge) {
      store.update({ settings });
      return;
    }
    const { terrain } = s.committed;
    terrain.maxEdge = settings.maxEdge;
    store.update({ settings, committed: { terrain, structure: readStructure(terrain) } });
  });
  store.subscribe((s) => panel.set(s.settings), ['settings']);
}
