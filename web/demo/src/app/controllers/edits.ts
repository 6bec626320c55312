// Terrain editing: every change of the points goes through commit(), which
// builds the new terrain (or says why not and keeps the old one) and puts it in
// the store with its history; the solver, the views and the link follow the
// store. Dragging a point draws a preview terrain, once a frame.
import type { Hodt } from 'hodt';
import { MAX_POINTS } from '../../share/urlState.ts';
import type { SolveSettings } from '../../ui/objectivePanel.ts';
import type { Notice } from '../../ui/notice.ts';
import type { TerrainSource } from '../../ui/terrainPanel.ts';
import type { PlanHandlers } from '../../views/plan/planView.ts';
import { readStructure } from '../analysis.ts';
import type { AppState, Snapshot } from '../appState.ts';
import { pushHistory, redoHistory, undoHistory, type History } from '../history.ts';
import { committedPicture, previewPicture } from '../picture.ts';
import { heightAt } from '../heightAt.ts';
import { addPoint, movePoint, pointAt, removePoint } from '../pointEdits.ts';
import type { ViewMode } from '../settings.ts';
import type { Store } from '../store.ts';
import { buildTerrain } from '../terrainBuild.ts';

export interface CommitOptions {
  /** The history after the edit: undo and redo pass the one they step to;
   * any other edit is recorded under its label. */
  history?: History<Snapshot>;
  source?: TerrainSource | null;
  reframe?: boolean;
  select?: number | null;
  /** Prefix of the message if the points are refused. */
  refused?: string;
  /** Settings and view that come with the points (a link, an import, a lesson):
   * the terrain is built in these settings' domain. */
  settings?: SolveSettings;
  view?: ViewMode;
  /** The height exaggeration of the first picture (from a link). */
  exaggeration?: number | null;
}

export interface Edits {
  /** Makes points the page's terrain, or shows why not; false if refused. */
  commit(next: Float64Array, label: string, o?: CommitOptions): boolean;
  /** A drag in progress: draws the points with point index moved. */
  drag(index: number, next: Float64Array): void;
  /** Draws what was committed again (after a refused edit or a drag that did not move). */
  redraw(): void;
  undo(): void;
  redo(): void;
  deleteSelected(): void;
  select(index: number | null): void;
}

/** Do a and b hold the same points, except perhaps point i? */
function sameExcept(a: Float64Array, b: Float64Array, i: number): boolean {
  if (a.length !== b.length) return false;
  for (let k = 0; k < a.length; ++k) if (a[k] !== b[k] && Math.floor(k / 3) !== i) return false;
  return true;
}

export function createEdits(store: Store<AppState>, hodt: Hodt, notice: Notice): Edits {
  function disposePreview(): void {
    store.get().preview?.terrain.dispose();
  }

  function redraw(): void {
    disposePreview();
    const s = store.get();
    store.update({ preview: null, dragTarget: null, shown: committedPicture(s) });
  }

  function commit(next: Float64Array, label: string, o: CommitOptions = {}): boolean {
    const s = store.get();
    if (next.length / 3 > MAX_POINTS) {
      notice.show(`${o.refused ?? 'Refused'}: ${(next.length / 3).toLocaleString('en')} points; the demo takes at most ${MAX_POINTS.toLocaleString('en')}. Your points are unchanged.`);
      return false;
    }
    const settings = o.settings ?? s.settings;
    const built = buildTerrain(hodt, next, settings.maxEdge);
    if (!built.ok) {
      notice.show(`${o.refused ?? `Cannot ${label}`}: ${built.message}. Your points are unchanged.`);
      redraw();
      return false;
    }
    notice.hide();
    disposePreview();
    s.committed.terrain.dispose();
    const source = o.source ?? null;
    const history = o.history ?? pushHistory(s.history, { points: next, source }, label);
    const selected = o.select === undefined ? (s.selected !== null && s.selected < next.length / 3 ? s.selected : null) : o.select;
    store.update({
      points: next,
      source,
      settings,
      view: o.view ?? s.view,
      committed: { terrain: built.terrain, structure: built.structure },
      preview: null,
      dragTarget: null,
      history,
      selected,
      reframe: s.reframe || o.reframe === true,
      ...(o.exaggeration !== undefined ? { linkedExaggeration: o.exaggeration } : {}),
    });
    return true;
  }

  function drag(index: number, next: Float64Array): void {
    const queued = store.get().dragTarget !== null;
    store.update({ dragTarget: { index, points: next } });
    if (queued) return;
    requestAnimationFrame(() => {
      const target = store.get().dragTarget;
      if (!target) return; // committed or redrawn meanwhile
      store.update({ dragTarget: null });
      const { index: i, points } = target;
      const s = store.get();
      // The first frame of a drag builds a preview terrain; later frames move the
      // point in it (a live edit: the library updates the triangulation around it).
      if (s.preview && sameExcept(s.preview.terrain.points, points, i)) {
        try {
          s.preview.terrain.movePoint(i, points[3 * i]!, points[3 * i + 1]!, points[3 * i + 2]!);
        } catch {
          return; // e.g. on top of another point: keep the last good picture
        }
        const preview = { ...s.preview, structure: readStructure(s.preview.terrain, false) };
        store.update({ preview, shown: previewPicture(preview, points) });
        return;
      }
      const built = buildTerrain(hodt, points, s.settings.maxEdge, false);
      if (!built.ok) return; // e.g. on top of another point: keep the last good picture
      disposePreview();
      const preview = { terrain: built.terrain, structure: built.structure };
      store.update({ preview, shown: previewPicture(preview, points) });
    });
  }

  function deleteSelected(): void {
    const s = store.get();
    if (s.selected === null) return;
    if (s.points.length / 3 <= 3) {
      notice.show('A terrain needs at least 3 points.');
      return;
    }
    commit(removePoint(s.points, s.selected), 'delete point', { select: null });
  }

  function undo(): void {
    const back = undoHistory(store.get().history);
    if (back) commit(back.state.points, 'undo', { history: back.history, source: back.state.source });
  }

  function redo(): void {
    const forward = redoHistory(store.get().history);
    if (forward) commit(forward.state.points, 'redo', { history: forward.history, source: forward.state.source });
  }

  return { commit, drag, redraw, undo, redo, deleteSelected, select: (index) => store.update({ selected: index }) };
}

/** The plan view's gestures as edits: a click selects or adds a point (at the
 * height of the surface shown there), a drag moves one. */
export function planHandlers(store: Store<AppState>, edits: Edits): PlanHandlers {
  return {
    select: (i) => edits.select(i),
    add: (x, y) => {
      const { points, shown } = store.get();
      const z = shown ? heightAt(shown, x, y) : 0;
      edits.commit(addPoint(points, x, y, z), 'add point', { select: points.length / 3 });
    },
    drag: (i, x, y, z) => edits.drag(i, movePoint(store.get().points, i, x, y, z)),
    dragEnd: (i, x, y, z) => {
      const { points } = store.get();
      const p = pointAt(points, i);
      const label = p.x === x && p.y === y ? 'change height' : 'move point';
      if (p.x === x && p.y === y && p.z === z) return edits.redraw();
      edits.commit(movePoint(points, i, x, y, z), label, { select: i });
    },
  };
}
