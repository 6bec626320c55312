/** Undo and redo over immutable snapshots (here: point arrays), as a value: every
 * step returns a new history, so the page's store can hold it. */
export interface History<T> {
  /** Every state up to the current one (the last entry), with the edit that reached it. */
  readonly past: readonly { state: T; label: string }[];
  /** States undone, the next redo last. */
  readonly future: readonly { state: T; label: string }[];
}

export function startHistory<T>(initial: T): History<T> {
  return { past: [{ state: initial, label: '' }], future: [] };
}

/** Records the state reached by an edit; clears the redo stack. */
export function pushHistory<T>(h: History<T>, state: T, label: string, limit = 200): History<T> {
  const past = [...h.past, { state, label }];
  return { past: past.length > limit + 1 ? past.slice(past.length - limit - 1) : past, future: [] };
}

/** The history one edit back and the state it returns to, or null. */
export function undoHistory<T>(h: History<T>): { history: History<T>; state: T } | null {
  if (h.past.length < 2) return null;
  const past = h.past.slice(0, -1);
  return { history: { past, future: [...h.future, h.past.at(-1)!] }, state: past.at(-1)!.state };
}

export function redoHistory<T>(h: History<T>): { history: History<T>; state: T } | null {
  const next = h.future.at(-1);
  if (!next) return null;
  return { history: { past: [...h.past, next], future: h.future.slice(0, -1) }, state: next.state };
}

/** The edit an undo would take back, or null. */
export const undoLabel = <T>(h: History<T>): string | null => (h.past.length >= 2 ? h.past.at(-1)!.label : null);
export const redoLabel = <T>(h: History<T>): string | null => h.future.at(-1)?.label ?? null;
