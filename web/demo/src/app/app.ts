import type { Hodt } from 'hodt';
import { createSolverClient } from '../solver/solverClient.ts';
import { byId } from '../ui/dom.ts';
import { renderLegend } from '../ui/legend.ts';
import { createNotice } from '../ui/notice.ts';
import { createObjectivePanel } from '../ui/objectivePanel.ts';
import { createResultCard } from '../ui/resultCard.ts';
import { createSelectionPanel } from '../ui/selectionPanel.ts';
import { createTerrainPanel } from '../ui/terrainPanel.ts';
import { createToolbar } from '../ui/toolbar.ts';
import { createPlanView } from '../views/plan/planView.ts';
import { createTerrainScene } from '../views/three/terrainScene.ts';
import { createViewer } from '../views/three/viewer.ts';
import { initialState } from './appState.ts';
import { connectDisplay } from './controllers/display.ts';
import { createEdits, planHandlers } from './controllers/edits.ts';
import { connectLink } from './controllers/link.ts';
import { connectResultCard } from './controllers/resultCard.ts';
import { connectSelection } from './controllers/selection.ts';
import { connectSolveSettings } from './controllers/solveSettings.ts';
import { createSolving } from './controllers/solving.ts';
import { connectTeach } from './controllers/teach.ts';
import { connectTerrainFiles } from './controllers/terrainFiles.ts';
import { connectUndoRedo } from './controllers/undoRedo.ts';
import { connectUsefulEdges } from './controllers/usefulEdges.ts';
import { connectViewSwitch } from './controllers/viewSwitch.ts';
import { createStore } from './store.ts';
import { publishHooks } from './testHooks.ts';

/** The page: one store (appState.ts) and the controllers that keep the panels,
 * the views, the solver and the link in step with it. */
export function startApp(hodt: Hodt): void {
  const notice = createNotice();
  const objectives = hodt.objectives;
  const objectivePanel = createObjectivePanel(objectives);
  const toolbar = createToolbar();
  renderLegend();
  const viewer = createViewer(byId('view-3d'));
  const scene = createTerrainScene();
  viewer.world.add(scene.object);

  const initial = initialState(hodt, location.hash, objectivePanel.showUseful);
  const store = createStore(initial.state);
  const edits = createEdits(store, hodt, notice);
  const plan = createPlanView(byId('view-plan'), planHandlers(store, edits));
  byId('plan-fit').addEventListener('click', () => plan.fit());

  // Listeners hear a change in the order they are connected: the solve starts,
  // the views are drawn, then the panels and the link follow.
  const solving = createSolving(store, createSolverClient());
  connectDisplay(store, { scene, plan, viewer, toolbar, objectivePanel, objectives });
  connectSelection(store, edits, { plan, scene, viewer, panel: createSelectionPanel() });
  connectResultCard(store, createResultCard(), objectives, () => solving.cancel());
  connectSolveSettings(store, objectivePanel);
  connectUsefulEdges(store, { plan, objectivePanel });
  connectTerrainFiles(store, edits, hodt, { panel: createTerrainPanel(), notice });
  connectUndoRedo(store, edits, toolbar);
  connectViewSwitch(store, toolbar);
  connectTeach(store, edits, hodt);
  const link = connectLink(store, edits, { toolbar, notice, scene });
  publishHooks(store, { plan, scene, viewer, link: link.link });

  if (initial.message) notice.show(initial.message);
  solving.solve(false);
}
