// The "useful edges" toggle: the useful order-k edges of the committed terrain
// in the plan view, and their count under the order control.
import type { ObjectivePanel } from '../../ui/objectivePanel.ts';
import type { PlanView } from '../../views/plan/planView.ts';
import type { AppState } from '../appState.ts';
import type { Store } from '../store.ts';

export function connectUsefulEdges(store: Store<AppState>, o: { plan: PlanView; objectivePanel: ObjectivePanel }): void {
  const { plan, objectivePanel } = o;

  function draw(s: AppState): void {
    if (!s.showUseful) {
      plan.setUseful(null);
      objectivePanel.setUsefulCount(null);
      return;
    }
    const k = s.settings.order;
    const terrain = s.committed.terrain;
    let useful = s.useful;
    if (!useful || useful.terrain !== terrain || useful.order !== k) {
      useful = { terrain, order: k, edges: terrain.usefulEdges(k) };
      store.update({ useful });
    }
    plan.setUseful(useful.edges);
    const count = useful.edges.length / 2;
    const name = k === 1 ? 'first order' : `order-${k}`;
    objectivePanel.setUsefulCount(
      `${count.toLocaleString('en')} useful ${name} edges: the edges of some ${name} Delaunay triangulation (violet lines where the shown triangulation does not use them, a violet halo where it does).`,
    );
  }

  objectivePanel.onUseful((show) => store.update({ showUseful: show }));
  store.subscribe((s, p) => {
    if (s.showUseful !== p.showUseful || s.committed !== p.committed || s.settings.order !== p.settings.order) draw(s);
  }, ['showUseful', 'committed', 'settings']);
}
