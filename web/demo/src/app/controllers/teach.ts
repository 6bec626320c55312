// The Teach tab: its views read the page's terrain and settings from the store,
// hear when they change, and may load points or choose settings like the sidebar.
import type { Hodt } from 'hodt';
import { createSolverClient } from '../../solver/solverClient.ts';
import { createTeachPanel } from '../../teach/teachPanel.ts';
import type { AppState } from '../appState.ts';
import type { Store } from '../store.ts';
import type { Edits } from './edits.ts';

export function connectTeach(store: Store<AppState>, edits: Edits, hodt: Hodt): void {
  const teach = createTeachPanel({
    hodt,
    terrain: () => store.get().committed.terrain,
    points: () => store.get().points,
    settings: () => store.get().settings,
    load: (next, label, objective, from) => {
      const { settings } = store.get();
      const chosen = objective && objective !== settings.objective ? { ...settings, objective, order: 1 } : settings;
      const loaded = edits.commit(next, label, { reframe: true, select: null, source: from ?? null, settings: chosen });
      if (!loaded) store.update({ settings: chosen });
    },
    showViews: () => store.update({ view: 'split' }),
    choose: (change) => {
      const { settings } = store.get();
      const next = { ...settings, ...change };
      if (next.objective === settings.objective && next.epsilon === settings.epsilon) return;
      store.update({ settings: next });
    },
    solver: createSolverClient(),
  });
  teach.setVisible(store.get().view === 'teach');
  store.subscribe(
    (s, p) => {
      // Told first, so that a view shown by the same change computes once.
      if (s.committed !== p.committed || s.settings !== p.settings) teach.changed();
      if (s.view !== p.view) teach.setVisible(s.view === 'teach');
    },
    ['committed', 'settings', 'view'],
  );
}
