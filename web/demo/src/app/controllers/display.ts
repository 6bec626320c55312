// Drawing: the store's picture (`shown`) in the 3D and plan views, with the
// counts above them and the measures table; the 3D camera framed on the first
// picture of a terrain (and kept on the points after edits) whenever the 3D view
// is on screen.
import type { ObjectiveInfo } from 'hodt';
import { byId } from '../../ui/dom.ts';
import { renderMeasures } from '../../ui/measuresTable.ts';
import type { ObjectivePanel } from '../../ui/objectivePanel.ts';
import type { Toolbar } from '../../ui/toolbar.ts';
import type { PlanView } from '../../views/plan/planView.ts';
import type { TerrainScene } from '../../views/three/terrainScene.ts';
import type { Viewer } from '../../views/three/viewer.ts';
import { countFlipped } from '../analysis.ts';
import type { AppState } from '../appState.ts';
import type { Store } from '../store.ts';

export function connectDisplay(
  store: Store<AppState>,
  o: { scene: TerrainScene; plan: PlanView; viewer: Viewer; toolbar: Toolbar; objectivePanel: ObjectivePanel; objectives: readonly ObjectiveInfo[] },
): void {
  const { scene, plan, viewer, toolbar } = o;

  function paint(s: AppState): void {
    const a = s.shown!;
    const reframe = s.reframe;
    scene.show(a, reframe, reframe ? s.linkedExaggeration : null);
    if (reframe) store.update({ reframe: false, linkedExaggeration: null, cameraFramed: false });
    const ex = scene.frame?.exaggeration ?? 1;
    byId('exaggeration').textContent = Math.abs(ex - 1) < 0.05 ? '' : ` · heights ×${ex < 10 ? ex.toFixed(1) : Math.round(ex)}`;
    plan.show(a);
    if (reframe) plan.fit();
    frameCameraIfVisible();
    viewer.invalidate();
    toolbar.setCounts({
      points: a.points.length / 3,
      triangles: a.triangles.length / 3,
      quads: a.quads.length / 4,
      flipped: a.changed ? (s.solution?.flipped ?? 0) : countFlipped(a.choice),
    });
    if (a.values && a.delaunayValues) renderMeasures(o.objectives, a.values, a.delaunayValues, s.settings.objective, (id) => o.objectivePanel.choose(id));
  }

  function frameCameraIfVisible(): void {
    const { cameraFramed, view } = store.get();
    if (cameraFramed && view !== 'plan') {
      // An edit may raise or move a point out of the framed view.
      requestAnimationFrame(() => viewer.keepInView(scene.worldPoints()));
      return;
    }
    if (cameraFramed || view === 'plan') return;
    requestAnimationFrame(() => {
      if (byId('view-3d').clientWidth === 0) return;
      viewer.frame(scene.worldPoints());
      store.update({ cameraFramed: true });
    });
  }

  store.subscribe((s) => s.shown && paint(s), ['shown']);
  store.subscribe(() => frameCameraIfVisible(), ['view']);
}
