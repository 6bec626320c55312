// Undo and redo: the toolbar's buttons and keys, their labels following the store.
import type { Toolbar } from '../../ui/toolbar.ts';
import type { AppState } from '../appState.ts';
import { redoLabel, undoLabel } from '../history.ts';
import { bindKeys } from '../keyboard.ts';
import type { Store } from '../store.ts';
import type { Edits } from './edits.ts';

export function connectUndoRedo(store: Store<AppState>, edits: Edits, toolbar: Toolbar): void {
  toolbar.onUndo(() => edits.undo());
  toolbar.onRedo(() => edits.redo());
  bindKeys({ undo: () => edits.undo(), redo: () => edits.redo(), deleteSelected: () => edits.deleteSelected(), deselect: () => edits.select(null) });
  toolbar.setHistory(null, null);
  store.subscribe((s) => toolbar.setHistory(undoLabel(s.history), redoLabel(s.history)), ['history']);
}
