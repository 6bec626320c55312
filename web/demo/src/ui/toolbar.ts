import type { ViewMode } from '../app/settings.ts';
import { byId } from './dom.ts';

export interface Counts {
  points: number;
  triangles: number;
  quads: number;
  flipped: number;
}

/** Counts, the view switch, undo/redo and the copy-link button above the views. */
export interface Toolbar {
  setCounts(c: Counts): void;
  setView(mode: ViewMode): void;
  setHistory(undo: string | null, redo: string | null): void;
  onView(handler: (mode: ViewMode) => void): void;
  onUndo(handler: () => void): void;
  onRedo(handler: () => void): void;
  onCopyLink(handler: () => void): void;
  /** Shows the link (selected, for manual copying) with a status line. */
  showLink(url: string | null, status: string): void;
  /** Hides the link (it no longer matches the state). */
  hideLink(): void;
}

export function createToolbar(): Toolbar {
  const stage = document.querySelector<HTMLElement>('.stage')!;
  const viewButtons = [...document.querySelectorAll<HTMLButtonElement>('.segmented button[data-view]')];
  const undo = byId<HTMLButtonElement>('undo');
  const redo = byId<HTMLButtonElement>('redo');
  const linkBox = byId('link-box');
  const link = byId<HTMLInputElement>('link');
  byId('link-close').addEventListener('click', () => (linkBox.hidden = true));
  const fmt = (n: number) => n.toLocaleString('en');

  return {
    setCounts(c) {
      byId('count-points').textContent = fmt(c.points);
      byId('count-triangles').textContent = fmt(c.triangles);
      byId('count-quads').textContent = fmt(c.quads);
      byId('count-flipped').textContent = fmt(c.flipped);
    },
    setView(mode) {
      stage.dataset.view = mode;
      for (const b of viewButtons) b.setAttribute('aria-pressed', String(b.dataset.view === mode));
    },
    setHistory(u, r) {
      undo.disabled = u === null;
      redo.disabled = r === null;
      undo.title = u ? `Undo ${u} (Ctrl+Z)` : 'Nothing to undo';
      redo.title = r ? `Redo ${r} (Ctrl+Shift+Z)` : 'Nothing to redo';
    },
    onView(handler) {
      for (const b of viewButtons) b.addEventListener('click', () => handler(b.dataset.view as ViewMode));
    },
    onUndo: (f) => undo.addEventListener('click', f),
    onRedo: (f) => redo.addEventListener('click', f),
    onCopyLink: (f) => byId('copy-link').addEventListener('click', f),
    showLink(url, status) {
      linkBox.hidden = false;
      byId('link-status').textContent = status;
      link.hidden = url === null;
      link.value = url ?? '';
      if (url) link.select();
    },
    hideLink() {
      linkBox.hidden = true;
    },
  };
}
