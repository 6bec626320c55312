// The view switch above the views: split, 3D, plan or Teach.
import type { Toolbar } from '../../ui/toolbar.ts';
import type { AppState } from '../appState.ts';
import type { Store } from '../store.ts';

export function connectViewSwitch(store: Store<AppState>, toolbar: Toolbar): void {
  toolbar.setView(store.get().view);
  toolbar.onView((view) => store.update({ view }));
  store.subscribe((s) => toolbar.setView(s.view), ['view']);
}
