import type { HodtTestHooks } from '../globals.d.ts';
import { pointsToCsv } from '../io/pointsCsv.ts';
import { solutionToJson } from '../io/solutionJson.ts';
import { byId } from '../ui/dom.ts';
import type { PlanView } from '../views/plan/planView.ts';
import type { TerrainScene } from '../views/three/terrainScene.ts';
import type { Viewer } from '../views/three/viewer.ts';
import { countFlipped } from './analysis.ts';
import type { AppState } from './appState.ts';
import { pointAt } from './pointEdits.ts';
import type { Store } from './store.ts';

/** Publishes the page's state for tests/e2e on window.__hodt: every field is
 * read from the store (or the views) when a test reads it. */
export function publishHooks(store: Store<AppState>, o: { plan: PlanView; scene: TerrainScene; viewer: Viewer; link: () => string | null }): void {
  const { plan, scene, viewer } = o;
  const s = () => store.get();
  const shown = () => s().shown;
  const hooks: HodtTestHooks = {
    get ready() {
      return shown() !== null;
    },
    get points() {
      return shown() ? shown()!.points.length / 3 : 0;
    },
    get triangles() {
      return shown() ? shown()!.triangles.length / 3 : 0;
    },
    get quads() {
      return shown() ? shown()!.quads.length / 4 : 0;
    },
    get flipped() {
      return shown() ? countFlipped(shown()!.choice) : 0;
    },
    get solving() {
      return s().solving;
    },
    get solves() {
      return s().solves;
    },
    get objective() {
      return s().settings.objective;
    },
    get method() {
      return s().settings.method;
    },
    get order() {
      return s().settings.order;
    },
    get exaggeration() {
      return scene.frame?.exaggeration ?? null;
    },
    get maxEdge() {
      return s().settings.maxEdge;
    },
    get outsideTriangles() {
      return shown() ? shown()!.inside.reduce((n, v) => n + (v === 0 ? 1 : 0), 0) : 0;
    },
    get usefulEdges() {
      const { showUseful, useful } = s();
      return showUseful && useful ? useful.edges.length / 2 : null;
    },
    get solution() {
      const { solution, committed } = s();
      return solution ? JSON.parse(solutionToJson(solution, committed.terrain)) : null;
    },
    get choice() {
      return shown() ? Array.from(shown()!.choice).join('') : '';
    },
    get selected() {
      return s().selected;
    },
    get notice() {
      return byId('notice').hidden ? null : byId('notice-text').textContent;
    },
    pointsCsv: () => pointsToCsv(s().points),
    planToClient: (x, y) => {
      const p = plan.toScreen(x, y);
      const r = plan.canvas.getBoundingClientRect();
      return { x: r.left + p.x, y: r.top + p.y };
    },
    threeToClient: (i) => {
      const p = scene.worldPoint(i).project(viewer.camera);
      const r = viewer.renderer.domElement.getBoundingClientRect();
      return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
    },
    point: (i) => pointAt(s().points, i),
    link: o.link,
  };
  window.__hodt = hooks;
}
