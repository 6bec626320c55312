// One state object and the only way to change it. Every change is a new object
// (the old one is never mutated), so a listener can compare fields by identity
// to see what changed. A listener may update the store itself: that change is
// delivered after the current one has reached every listener, so every listener
// hears every change, in the order they were made.

export type Listener<S> = (state: S, previous: S) => void;

export interface Store<S extends object> {
  /** The current state (frozen: change it with update). */
  get(): Readonly<S>;
  /** Replaces the given fields. Nothing happens when every one of them already
   * holds that very value. */
  update(change: Partial<S>): void;
  /** Calls listener after each change with the new state and the one before;
   * with keys, only after changes to one of those fields. Returns the function
   * that stops it. */
  subscribe(listener: Listener<S>, keys?: readonly (keyof S)[]): () => void;
}

export function createStore<S extends object>(initial: S): Store<S> {
  let state: Readonly<S> = Object.freeze({ ...initial });
  const listeners: { listener: Listener<S>; keys: readonly (keyof S)[] | undefined }[] = [];
  const queue: [Readonly<S>, Readonly<S>][] = [];
  let delivering = false;

  function deliver(): void {
    delivering = true;
    try {
      for (let change = queue.shift(); change; change = queue.shift()) {
        const [next, previous] = change;
        for (const { listener, keys } of [...listeners]) {
          if (!keys || keys.some((k) => !Object.is(next[k], previous[k]))) listener(next, previous);
        }
      }
    } finally {
      queue.length = 0;
      delivering = false;
    }
  }

  return {
    get: () => state,
    update(change) {
      const keys = Object.keys(change) as (keyof S)[];
      if (keys.every((k) => Object.is(state[k], change[k]))) return;
      const previous = state;
      state = Object.freeze({ ...state, ...change });
      queue.push([state, previous]);
      if (!delivering) deliver();
    },
    subscribe(listener, keys) {
      const entry = { listener, keys };
      listeners.push(entry);
      return () => {
        const i = listeners.indexOf(entry);
        if (i >= 0) listeners.splice(i, 1);
      };
    },
  };
}
