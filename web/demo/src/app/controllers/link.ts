// The link: the URL hash follows the state (so that reloading or copying the
// address bar keeps it), Copy link shows and copies it, and a link pasted into
// the address bar opens its terrain and settings.
import { decodeState, type SharedState } from '../../share/urlState.ts';
import type { Notice } from '../../ui/notice.ts';
import type { Toolbar } from '../../ui/toolbar.ts';
import type { TerrainScene } from '../../views/three/terrainScene.ts';
import { settingsOf, type AppState } from '../appState.ts';
import type { Store } from '../store.ts';
import { createUrlSync } from '../urlSync.ts';
import type { Edits } from './edits.ts';

export interface Link {
  /** The link to the current state, or null if it would be too long. */
  link(): string | null;
}

export function connectLink(store: Store<AppState>, edits: Edits, o: { toolbar: Toolbar; notice: Notice; scene: TerrainScene }): Link {
  const { toolbar, notice, scene } = o;
  const urlSync = createUrlSync((): SharedState => {
    const s = store.get();
    // The exaggeration in use, or the one a link asked for before it is drawn.
    return { points: s.points, ...s.settings, view: s.view, source: s.source, exaggeration: scene.frame?.exaggeration ?? s.linkedExaggeration };
  });

  async function copyLink(): Promise<void> {
    const url = urlSync.link();
    if (!url) {
      toolbar.showLink(null, 'Too many points for a link: export the points as CSV instead.');
      return;
    }
    const size = `${(url.length / 1024).toFixed(1)} KB`;
    toolbar.showLink(url, `Copy this link (${size}):`); // at once; the clipboard may take a while
    try {
      await navigator.clipboard.writeText(url);
      toolbar.showLink(url, `Link copied (${size}).`);
    } catch {
      toolbar.showLink(url, `Copy this link (${size}):`);
    }
  }

  window.addEventListener('hashchange', () => {
    try {
      const s = decodeState(location.hash);
      if (!s) return;
      const settings = settingsOf(s);
      const opened = edits.commit(s.points, 'open link', { source: s.source, reframe: true, select: null, refused: 'Cannot open the link', settings, view: s.view, exaggeration: s.exaggeration });
      // Refused points leave the link's settings and view, but not its exaggeration.
      if (!opened) store.update({ settings, view: s.view, linkedExaggeration: null });
    } catch (e) {
      notice.show(`${e instanceof Error ? e.message : String(e)}. Your points are unchanged.`);
    }
  });
  toolbar.onCopyLink(() => void copyLink());
  // A shown link no longer matches once the points or settings change.
  store.subscribe(() => toolbar.hideLink(), ['points', 'settings']);
  store.subscribe(() => urlSync.changed(), ['points', 'source', 'settings', 'view']);
  urlSync.changed();
  return { link: () => urlSync.link() };
}
