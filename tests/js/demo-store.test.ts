// The demo's store (web/demo/src/app/store.ts) and its undo history
// (app/history.ts): one state, changed only by update, heard by every listener
// in the order of the changes, also when a listener changes it again.
import { describe, expect, test } from 'vitest';
import { createStore } from '../../web/demo/src/app/store.ts';
import { pushHistory, redoHistory, redoLabel, startHistory, undoHistory, undoLabel } from '../../web/demo/src/app/history.ts';

interface S {
  a: number;
  b: string;
  list: number[];
}

describe('demo store', () => {
  test('update replaces the given fields in a new frozen state; get reads it', () => {
    const store = createStore<S>({ a: 1, b: 'x', list: [1] });
    const before = store.get();
    store.update({ a: 2 });
    const after = store.get();
    expect(after).toEqual({ a: 2, b: 'x', list: [1] });
    expect(after).not.toBe(before);
    expect(before.a).toBe(1);
    expect(after.list).toBe(before.list);
    expect(Object.isFrozen(after)).toBe(true);
    expect(() => {
      (after as S).a = 5;
    }).toThrow(TypeError);
  });

  test('listeners hear each change with the state before it; an update to the same values is no change', () => {
    const store = createStore<S>({ a: 1, b: 'x', list: [] });
    const heard: [number, number][] = [];
    store.subscribe((s, p) => heard.push([s.a, p.a]));
    store.update({ a: 2 });
    store.update({ a: 2, b: 'x' });
    store.update({ a: 3 });
    expect(heard).toEqual([
      [2, 1],
      [3, 2],
    ]);
    // A new array is a change even when it holds the same numbers.
    store.update({ list: [] });
    expect(heard).toHaveLength(3);
  });

  test('a listener with keys hears only changes to those fields', () => {
    const store = createStore<S>({ a: 1, b: 'x', list: [] });
    const bs: string[] = [];
    store.subscribe((s) => bs.push(s.b), ['b']);
    store.update({ a: 2 });
    store.update({ b: 'y' });
    store.update({ a: 3, b: 'z' });
    expect(bs).toEqual(['y', 'z']);
  });

  test('an update made by a listener reaches every listener after the change being delivered, in order', () => {
    const store = createStore<S>({ a: 0, b: '', list: [] });
    const log: string[] = [];
    store.subscribe((s, p) => {
      log.push(`first ${p.a}->${s.a}`);
      if (s.a === 1) store.update({ a: 2 });
    });
    store.subscribe((s, p) => log.push(`second ${p.a}->${s.a} (store ${store.get().a})`));
    store.update({ a: 1 });
    expect(log).toEqual(['first 0->1', 'second 0->1 (store 2)', 'first 1->2', 'second 1->2 (store 2)']);
    expect(store.get().a).toBe(2);
  });

  test('unsubscribe stops a listener; a listener that throws does not block later updates', () => {
    const store = createStore<S>({ a: 0, b: '', list: [] });
    const seen: number[] = [];
    const stop = store.subscribe((s) => seen.push(s.a));
    store.update({ a: 1 });
    stop();
    store.update({ a: 2 });
    expect(seen).toEqual([1]);
    const off = store.subscribe(() => {
      throw new Error('boom');
    });
    expect(() => store.update({ a: 3 })).toThrow('boom');
    off();
    store.subscribe((s) => seen.push(s.a));
    store.update({ a: 4 });
    expect(seen).toEqual([1, 4]);
  });
});

describe('demo undo history', () => {
  test('undo and redo walk the snapshots and their labels without changing the history they were given', () => {
    let h = startHistory('p0');
    expect(undoHistory(h)).toBeNull();
    h = pushHistory(h, 'p1', 'add point');
    h = pushHistory(h, 'p2', 'move point');
    expect(undoLabel(h)).toBe('move point');
    expect(redoLabel(h)).toBeNull();
    const back = undoHistory(h)!;
    expect(back.state).toBe('p1');
    expect(undoLabel(h)).toBe('move point');
    expect(undoLabel(back.history)).toBe('add point');
    expect(redoLabel(back.history)).toBe('move point');
    const again = redoHistory(back.history)!;
    expect(again.state).toBe('p2');
    expect(again.history).toEqual(h);
    // A new edit after an undo drops what could be redone.
    const edited = pushHistory(back.history, 'p3', 'delete point');
    expect(redoHistory(edited)).toBeNull();
    expect(undoHistory(edited)!.state).toBe('p1');
  });

  test('the history keeps the last `limit` edits', () => {
    let h = startHistory(0);
    for (let i = 1; i <= 10; i++) h = pushHistory(h, i, `edit ${i}`, 3);
    const states: number[] = [];
    for (let u = undoHistory(h); u; u = undoHistory(u.history)) states.push(u.state);
    expect(states).toEqual([9, 8, 7]);
  });
});
