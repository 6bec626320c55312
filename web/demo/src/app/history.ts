/** Undo and redo over immutable snapshots (here: point arrays). */
export interface History<T> {
  /** Records the state reached by an edit; clears the redo stack. */
  push(state: T, label: string): void;
  /** The state before the last edit, or null. */
  undo(): T | null;
  redo(): T | null;
  /** Forgets everything and starts from state. */
  reset(state: T): void;
  readonly undoLabel: string | null;
  readonly redoLabel: string | null;
}

export function createHistory<T>(initial: T, limit = 200): History<T> {
  // past holds every state up to the current one (the last entry).
  let past: { state: T; label: string }[] = [{ state: initial, label: '' }];
  let future: { state: T; label: string }[] = [];
  return {
    push(state, label) {
      past.push({ state, label });
      if (past.length > limit + 1) past = past.slice(past.length - limit - 1);
      future = [];
    },
    undo() {
      if (past.length < 2) return null;
      future.push(past.pop()!);
      return past[past.length - 1]!.state;
    },
    redo() {
      const next = future.pop();
      if (!next) return null;
      past.push(next);
      return next.state;
    },
    reset(state) {
      past = [{ state, label: '' }];
      future = [];
    },
    get undoLabel() {
      return past.length >= 2 ? past[past.length - 1]!.label : null;
    },
    get redoLabel() {
      return future.length ? future[future.length - 1]!.label : null;
    },
  };
}
