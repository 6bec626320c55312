// The selected point: marked in both views, described and editable in the
// selection panel; picked by a click on the 3D terrain.
import type { SelectionPanel } from '../../ui/selectionPanel.ts';
import type { PlanView } from '../../views/plan/planView.ts';
import type { TerrainScene } from '../../views/three/terrainScene.ts';
import type { Viewer } from '../../views/three/viewer.ts';
import { onClickPick } from '../../views/three/clickPick.ts';
import type { AppState } from '../appState.ts';
import { describeVertex } from '../describeVertex.ts';
import { movePoint, pointAt } from '../pointEdits.ts';
import type { Store } from '../store.ts';
import type { Edits } from './edits.ts';

export function connectSelection(store: Store<AppState>, edits: Edits, o: { plan: PlanView; scene: TerrainScene; viewer: Viewer; panel: SelectionPanel }): void {
  const { plan, scene, viewer, panel } = o;

  /** The panel describes the selected point in the picture on screen. */
  function describe(s: AppState): void {
    if (s.selected === null || !s.shown || s.selected >= s.shown.points.length / 3) {
      panel.show(null);
      return;
    }
    const i = s.selected;
    panel.show({ index: i, ...pointAt(s.shown.points, i), about: describeVertex(s.shown, i) });
  }

  store.subscribe(
    (s, p) => {
      if (s.selected !== p.selected) {
        plan.select(s.selected);
        scene.select(s.selected);
        viewer.invalidate();
      }
      // An edit that moves the selection is described once its picture is drawn.
      if (s.shown !== p.shown || s.committed === p.committed) describe(s);
    },
    ['selected', 'shown'],
  );

  panel.onEdit((i, x, y, z) => {
    const { points } = store.get();
    const p = pointAt(points, i);
    if (p.x !== x || p.y !== y || p.z !== z) edits.commit(movePoint(points, i, x, y, z), 'edit point', { select: i });
  });
  panel.onDelete(() => edits.deleteSelected());

  onClickPick(viewer, scene, (i) => edits.select(i));
}
