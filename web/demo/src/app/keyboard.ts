export interface KeyActions {
  undo(): void;
  redo(): void;
  deleteSelected(): void;
  deselect(): void;
}

/** Ctrl/Cmd+Z undo, Ctrl/Cmd+Shift+Z or Ctrl+Y redo, Delete/Backspace removes the
 * selected point, Escape deselects. Ignored while typing in a field. */
export function bindKeys(actions: KeyActions): void {
  window.addEventListener('keydown', (e) => {
    const target = e.target as HTMLElement | null;
    const typing = Boolean(target?.closest?.('input, select, textarea'));
    const mod = e.ctrlKey || e.metaKey;
    const key = e.key.toLowerCase();
    if (mod && key === 'z' && !typing) {
      e.preventDefault();
      if (e.shiftKey) actions.redo();
      else actions.undo();
    } else if (mod && key === 'y' && !typing) {
      e.preventDefault();
      actions.redo();
    } else if ((e.key === 'Delete' || e.key === 'Backspace') && !typing) {
      e.preventDefault();
      actions.deleteSelected();
    } else if (e.key === 'Escape' && !typing) {
      actions.deselect();
    }
  });
}
