import { InputError, type Hodt, type ObjectiveInfo, type ParsedPoints, type ProgressInfo, type Solution } from 'hodt';
import { Vector2 } from 'three';
import { download } from '../io/download.ts';
import { meshFile } from '../io/meshExport.ts';
import { pointsToCsv } from '../io/pointsCsv.ts';
import { readTextFile } from '../io/readTextFile.ts';
import { solutionToJson } from '../io/solutionJson.ts';
import { decodeState, LinkError, MAX_POINTS, type SharedState } from '../share/urlState.ts';
import { createSolverClient } from '../solver/solverClient.ts';
import { TERRAINS } from '../terrains/catalog.ts';
import { byId } from '../ui/dom.ts';
import { attachDropZone } from '../ui/dropZone.ts';
import { renderLegend } from '../ui/legend.ts';
import { renderMeasures } from '../ui/measuresTable.ts';
import { createNotice } from '../ui/notice.ts';
import { createObjectivePanel, type SolveSettings } from '../ui/objectivePanel.ts';
import { createResultCard } from '../ui/resultCard.ts';
import { createSelectionPanel } from '../ui/selectionPanel.ts';
import { createTerrainPanel, type ExportFormat, type TerrainSource } from '../ui/terrainPanel.ts';
import { createToolbar } from '../ui/toolbar.ts';
import { createPlanView } from '../views/plan/planView.ts';
import { createTerrainScene } from '../views/three/terrainScene.ts';
import { createViewer } from '../views/three/viewer.ts';
import { analyse, analyseTriangles, countFlipped, readStructure, type Analysis } from './analysis.ts';
import { dropDuplicateXY } from './dedupe.ts';
import { describeVertex } from './describeVertex.ts';
import { heightAt } from './heightAt.ts';
import { createHistory } from './history.ts';
import { bindKeys } from './keyboard.ts';
import { addPoint, movePoint, pointAt, removePoint } from './pointEdits.ts';
import type { ViewMode } from './settings.ts';
import { buildTerrain, type Built } from './terrainBuild.ts';
import { publishHooks } from './testHooks.ts';
import { createUrlSync } from './urlSync.ts';
import { createTeachPanel } from '../teach/teachPanel.ts';

type Ready = Extract<Built, { ok: true }>;

/** Do a and b hold the same points, except perhaps point i? */
function sameExcept(a: Float64Array, b: Float64Array, i: number): boolean {
  if (a.length !== b.length) return false;
  for (let k = 0; k < a.length; ++k) if (a[k] !== b[k] && Math.floor(k / 3) !== i) return false;
  return true;
}

export const DEFAULT_SOURCE: TerrainSource = { kind: 'volcano', count: 200, seed: 7 };
const DEFAULT_SETTINGS: SolveSettings = { objective: 'min-mixed-vertices', method: 'auto', epsilon: 0.25, order: 1, maxEdge: null };
/** How long an edit waits for its solution before drawing Delaunay meanwhile. */
const SOLUTION_GRACE_MS = 150;

/** The page: state (points, settings, view, selection), its history, the
 * solver worker, and every view and panel, kept in step. */
export function startApp(hodt: Hodt): void {
  const notice = createNotice();
  const objectives = hodt.objectives;
  const info = (id: string): ObjectiveInfo => objectives.find((o) => o.id === id)!;
  const objectivePanel = createObjectivePanel(objectives);
  const result = createResultCard();
  const terrainPanel = createTerrainPanel();
  const selectionPanel = createSelectionPanel();
  const toolbar = createToolbar();
  renderLegend();
  const viewer = createViewer(byId('view-3d'));
  const scene = createTerrainScene();
  viewer.world.add(scene.object);
  const solver = createSolverClient();

  // ---- state -------------------------------------------------------------
  const initial = readInitialState();
  let points = initial.points;
  let source = initial.source;
  let settings: SolveSettings = settingsOf(initial);
  let view: ViewMode = initial.view;
  let selected: number | null = null;
  let current: Ready = initial.built;
  let preview: Ready | null = null;
  let solution: Solution | null = null;
  let shown: Analysis | null = null;
  let solving = false;
  let solves = 0;
  let solveToken = 0;
  let reframePending = true;
  /** The height exaggeration of the next reframe (from a link); null: automatic. */
  let linkedExaggeration: number | null = initial.exaggeration;
  let cameraFramed = false;
  const history = createHistory({ points, source });
  const urlSync = createUrlSync(
    (): SharedState => ({ points, ...settings, view, source, exaggeration: scene.frame?.exaggeration ?? linkedExaggeration }),
  );

  const plan = createPlanView(byId('view-plan'), {
    select: (i) => select(i),
    add: (x, y) => {
      const z = shown ? heightAt(shown, x, y) : 0;
      commit(addPoint(points, x, y, z), 'add point', { select: points.length / 3 });
    },
    drag: (i, x, y, z) => dragPreview(i, movePoint(points, i, x, y, z)),
    dragEnd: (i, x, y, z) => {
      const p = pointAt(points, i);
      const label = p.x === x && p.y === y ? 'change height' : 'move point';
      if (p.x === x && p.y === y && p.z === z) return redraw();
      commit(movePoint(points, i, x, y, z), label, { select: i });
    },
  });

  // ---- drawing -----------------------------------------------------------
  function display(a: Analysis): void {
    shown = a;
    const reframe = reframePending;
    reframePending = false;
    scene.show(a, reframe, reframe ? linkedExaggeration : null);
    if (reframe) linkedExaggeration = null;
    const ex = scene.frame?.exaggeration ?? 1;
    byId('exaggeration').textContent = Math.abs(ex - 1) < 0.05 ? '' : ` · heights ×${ex < 10 ? ex.toFixed(1) : Math.round(ex)}`;
    if (reframe) {
      cameraFramed = false;
      plan.show(a);
      plan.fit();
    } else {
      plan.show(a);
    }
    frameCameraIfVisible();
    viewer.invalidate();
    toolbar.setCounts({
      points: a.points.length / 3,
      triangles: a.triangles.length / 3,
      quads: a.quads.length / 4,
      flipped: a.changed ? (solution?.flipped ?? 0) : countFlipped(a.choice),
    });
    if (a.values && a.delaunayValues) renderMeasures(objectives, a.values, a.delaunayValues, settings.objective, (id) => objectivePanel.choose(id));
    showSelection();
    hooks();
  }

  function frameCameraIfVisible(): void {
    if (cameraFramed && view !== 'plan') {
      // An edit may raise or move a point out of the framed view.
      requestAnimationFrame(() => viewer.keepInView(scene.worldPoints()));
      return;
    }
    if (cameraFramed || view === 'plan') return;
    requestAnimationFrame(() => {
      if (byId('view-3d').clientWidth === 0) return;
      viewer.frame(scene.worldPoints());
      cameraFramed = true;
    });
  }

  /** Draws the committed terrain with a choice (all zeros: Delaunay). */
  function showChoice(choice: Uint8Array | null, critical: Solution['critical'] = null): void {
    const m = current.structure.quads.length / 4;
    display(analyse(current.terrain, current.structure, points, choice ?? new Uint8Array(m), critical));
  }

  /** Draws a solution: a choice of diagonals (order 1) or, for order k >= 2,
   * its triangles. */
  function showSolution(s: Solution): void {
    if (s.order > 1) display(analyseTriangles(current.terrain, current.structure, points, s.triangles));
    else showChoice(s.choice, s.critical);
  }

  /** Redraws what was committed (after a refused edit or drag). */
  function redraw(): void {
    disposePreview();
    if (solution) showSolution(solution);
    else showChoice(null);
  }

  // ---- useful order-k edges ------------------------------------------------
  let useful: { terrain: unknown; order: number; edges: Uint32Array } | null = null;
  /** Draws (or hides) the useful order-k edges of the committed terrain. */
  function updateUseful(): void {
    if (!objectivePanel.showUseful) {
      plan.setUseful(null);
      objectivePanel.setUsefulCount(null);
      hooks();
      return;
    }
    const k = settings.order;
    if (!useful || useful.terrain !== current.terrain || useful.order !== k) {
      useful = { terrain: current.terrain, order: k, edges: current.terrain.usefulEdges(k) };
    }
    plan.setUseful(useful.edges);
    const count = useful.edges.length / 2;
    objectivePanel.setUsefulCount(
      `${count.toLocaleString('en')} useful ${k === 1 ? 'first order' : `order-${k}`} edges: the edges of some ${k === 1 ? 'first order' : `order-${k}`} Delaunay triangulation (violet lines where the shown triangulation does not use them, a violet halo where it does).`,
    );
    hooks();
  }

  // ---- solving -----------------------------------------------------------
  /** Solves the current objective on the current points in the worker. With
   * keepDisplay (same points, other settings) the old picture stays until the
   * answer; otherwise Delaunay is drawn if the answer takes a moment. */
  function solve(keepDisplay: boolean): void {
    const token = ++solveToken;
    const objective = info(settings.objective);
    solution = null;
    solving = true;
    result.running(objective, () => solver.cancel());
    hooks();
    const fallback = keepDisplay ? 0 : window.setTimeout(() => token === solveToken && !preview && showChoice(null), reframePending ? 0 : SOLUTION_GRACE_MS);
    const progress = (info: ProgressInfo) => token === solveToken && result.progress(info);
    // At order k the explanation brings the regions, counted as the Teach view counts them.
    void solver.solve({ points, ...settings, explain: settings.order > 1 }, progress).then((outcome) => {
      if (token !== solveToken) return; // superseded by a newer edit
      clearTimeout(fallback);
      solving = false;
      solves++;
      if (outcome.status === 'solved' && outcome.solution.order === 1 && outcome.solution.choice.length !== current.structure.quads.length / 4) {
        outcome = { status: 'failed', name: 'InternalError', message: 'the worker found a different set of quads' };
      }
      // While a point is dragged the preview stays; dropping it re-solves.
      if (outcome.status === 'solved') {
        // (Drawing can start another solve, e.g. an edit field that loses focus: keep this one's.)
        const solved = (solution = outcome.solution);
        if (!preview) showSolution(solved);
        result.solved(objective, solved, current.structure.quads.length / 4, outcome.explanation?.regions);
      } else {
        if (!preview) showChoice(null);
        if (outcome.status === 'failed') result.failed(objective, outcome.message, settings.order);
        else result.cancelled(objective);
      }
      hooks();
    });
  }

  // ---- edits -------------------------------------------------------------
  interface CommitOptions {
    /** Undo label; null for undo/redo themselves (not recorded). */
    record?: boolean;
    source?: TerrainSource | null;
    reframe?: boolean;
    select?: number | null;
    /** Prefix of the message if the points are refused. */
    refused?: string;
  }

  /** Makes points the current terrain: builds it (or shows why not and keeps the
   * old points), records the edit, redraws and re-solves. */
  function commit(next: Float64Array, label: string, o: CommitOptions = {}): boolean {
    if (next.length / 3 > MAX_POINTS) {
      notice.show(`${o.refused ?? 'Refused'}: ${(next.length / 3).toLocaleString('en')} points; the demo takes at most ${MAX_POINTS.toLocaleString('en')}. Your points are unchanged.`);
      return false;
    }
    const built = buildTerrain(hodt, next, settings.maxEdge);
    if (!built.ok) {
      notice.show(`${o.refused ?? `Cannot ${label}`}: ${built.message}. Your points are unchanged.`);
      redraw();
      return false;
    }
    notice.hide();
    toolbar.hideLink();
    disposePreview();
    current.terrain.dispose();
    current = built;
    points = next;
    source = o.source ?? null;
    if (o.record !== false) history.push({ points, source }, label);
    if (o.reframe) reframePending = true;
    selected = o.select === undefined ? (selected !== null && selected < points.length / 3 ? selected : null) : o.select;
    terrainPanel.set(source);
    scene.select(selected);
    plan.select(selected);
    toolbar.setHistory(history.undoLabel, history.redoLabel);
    urlSync.changed();
    updateUseful();
    teach.changed();
    solve(false);
    return true;
  }

  let dragTarget: { index: number; points: Float64Array } | null = null;
  function dragPreview(index: number, next: Float64Array): void {
    const queued = dragTarget !== null;
    dragTarget = { index, points: next };
    if (queued) return;
    requestAnimationFrame(() => {
      const { index: i, points: target } = dragTarget!;
      dragTarget = null;
      // The first frame of a drag builds a preview terrain; later frames move the
      // point in it (a live edit: the library updates the triangulation around it).
      if (preview && sameExcept(preview.terrain.points, target, i)) {
        try {
          preview.terrain.movePoint(i, target[3 * i]!, target[3 * i + 1]!, target[3 * i + 2]!);
        } catch {
          return; // e.g. on top of another point: keep the last good picture
        }
        preview = { ...preview, structure: readStructure(preview.terrain, false) };
        display(analyse(preview.terrain, preview.structure, target, new Uint8Array(preview.structure.quads.length / 4)));
        return;
      }
      const built = buildTerrain(hodt, target, settings.maxEdge, false);
      if (!built.ok) return; // e.g. on top of another point: keep the last good picture
      disposePreview();
      preview = built;
      display(analyse(built.terrain, built.structure, target, new Uint8Array(built.structure.quads.length / 4)));
    });
  }
  function disposePreview(): void {
    dragTarget = null;
    preview?.terrain.dispose();
    preview = null;
  }

  function select(i: number | null): void {
    selected = i;
    plan.select(i);
    scene.select(i);
    viewer.invalidate();
    showSelection();
    hooks();
  }
  function showSelection(): void {
    if (selected === null || !shown || selected >= shown.points.length / 3) {
      selectionPanel.show(null);
      return;
    }
    const i = selected;
    selectionPanel.show({ index: i, ...pointAt(shown.points, i), about: describeVertex(shown, i) });
  }
  function deleteSelected(): void {
    if (selected === null) return;
    if (points.length / 3 <= 3) {
      notice.show('A terrain needs at least 3 points.');
      return;
    }
    commit(removePoint(points, selected), 'delete point', { select: null });
  }
  function undo(): void {
    const s = history.undo();
    if (s) commit(s.points, 'undo', { record: false, source: s.source });
  }
  function redo(): void {
    const s = history.redo();
    if (s) commit(s.points, 'redo', { record: false, source: s.source });
  }

  async function importFile(file: File): Promise<void> {
    const refused = `Could not import ${file.name}`;
    let read: ParsedPoints;
    try {
      read = hodt.readPoints(await readTextFile(file), file.name);
    } catch (e) {
      if (!(e instanceof InputError) && !(e instanceof Error)) throw e;
      notice.show(`${refused}: ${e.message}. Your points are unchanged.`);
      return;
    }
    const { points: unique, removed } = dropDuplicateXY(read.points);
    // A raster with NODATA cells comes with its default domain; any other file
    // keeps the page's.
    const before = settings;
    if (read.maxEdge !== undefined) setSettings({ ...settings, maxEdge: read.maxEdge });
    if (!commit(unique, `import ${file.name}`, { reframe: true, select: null, refused })) {
      setSettings(before);
      return;
    }
    const notes: string[] = [];
    if (removed > 0) notes.push(`dropped ${removed} point${removed === 1 ? '' : 's'} at the same (x, y) as an earlier one`);
    if (read.maxEdge !== undefined) notes.push(`it has NODATA cells, so triangles with an edge longer than ${read.maxEdge} are outside the domain (greyed, not measured; see Longest edge)`);
    if (notes.length > 0) notice.show(`Imported ${file.name}: ${notes.join('; ')}.`, 'info');
  }

  function exportAs(format: ExportFormat): void {
    const base = `hodt-${settings.objective}`;
    const about = solution ? `${solution.objective} = ${solution.value} (Delaunay ${solution.delaunayValue})` : 'Delaunay triangulation';
    if (format === 'csv') download('hodt-points.csv', pointsToCsv(points), 'text/csv');
    else if (format !== 'json') {
      const { bytes, type } = meshFile(format, shown!, `hodt: ${about}`, settings.maxEdge !== null);
      download(`${base}.${format}`, bytes, type);
    } else if (solution) download(`${base}.json`, solutionToJson(solution), 'application/json');
    else notice.show('No solution to export yet: wait for the solver to finish.', 'info');
  }

  function setView(mode: ViewMode): void {
    view = mode;
    toolbar.setView(mode);
    teach.setVisible(mode === 'teach');
    frameCameraIfVisible();
    urlSync.changed();
  }

  async function copyLink(): Promise<void> {
    const url = urlSync.link();
    if (!url) {
      toolbar.showLink(null, 'Too many points for a link: export the points as CSV instead.');
      return;
    }
    const size = `${(url.length / 1024).toFixed(1)} KB`;
    toolbar.showLink(url, `Copy this link (${size}):`);  // at once; the clipboard may take a while
    try {
      await navigator.clipboard.writeText(url);
      toolbar.showLink(url, `Link copied (${size}).`);
    } catch {
      toolbar.showLink(url, `Copy this link (${size}):`);
    }
  }

  // ---- teaching views ------------------------------------------------------
  const teach = createTeachPanel({
    hodt,
    terrain: () => current.terrain,
    points: () => points,
    settings: () => settings,
    load: (next, label, objective, from) => {
      if (objective && objective !== settings.objective) {
        setSettings({ ...settings, objective, order: 1 });
      }
      commit(next, label, { reframe: true, select: null, source: from ?? null });
    },
    showViews: () => setView('split'),
    choose: (change) => {
      const next = { ...settings, ...change };
      if (next.objective === settings.objective && next.epsilon === settings.epsilon) return;
      setSettings(next);
      toolbar.hideLink();
      urlSync.changed();
      updateUseful();
      teach.changed();
      solve(true);
    },
    solver: createSolverClient(),
  });

  /** Settings set by the page (a link, an import, a lesson), not the panel. */
  function setSettings(s: SolveSettings): void {
    settings = s;
    objectivePanel.set(s);
  }

  // ---- wiring ------------------------------------------------------------
  objectivePanel.set(settings);
  objectivePanel.onChange((s) => {
    const domainChanged = s.maxEdge !== settings.maxEdge;
    settings = s;
    if (domainChanged) {
      // The same points in another domain: the values change, the quads do not.
      current.terrain.maxEdge = s.maxEdge;
      current = { ...current, structure: readStructure(current.terrain) };
    }
    toolbar.hideLink();
    urlSync.changed();
    updateUseful();
    teach.changed();
    solve(!domainChanged);
  });
  objectivePanel.onUseful(() => updateUseful());
  terrainPanel.set(source);
  terrainPanel.onGenerate((s) => {
    commit(TERRAINS[s.kind].make(s.count, s.seed), `load ${TERRAINS[s.kind].label.toLowerCase()}`, { source: s, reframe: true, select: null });
  });
  terrainPanel.onImport((f) => void importFile(f));
  terrainPanel.onExport(exportAs);
  attachDropZone((f) => void importFile(f));
  selectionPanel.onEdit((i, x, y, z) => {
    const p = pointAt(points, i);
    if (p.x !== x || p.y !== y || p.z !== z) commit(movePoint(points, i, x, y, z), 'edit point', { select: i });
  });
  selectionPanel.onDelete(() => deleteSelected());
  toolbar.setView(view);
  teach.setVisible(view === 'teach');
  toolbar.onView(setView);
  toolbar.onUndo(undo);
  toolbar.onRedo(redo);
  toolbar.onCopyLink(() => void copyLink());
  toolbar.setHistory(null, null);
  byId('plan-fit').addEventListener('click', () => plan.fit());
  bindKeys({ undo, redo, deleteSelected, deselect: () => select(null) });
  pickIn3d();
  window.addEventListener('hashchange', () => {
    try {
      const s = decodeState(location.hash);
      if (!s) return;
      setSettings(settingsOf(s));
      setView(s.view);
      linkedExaggeration = s.exaggeration;
      if (!commit(s.points, 'open link', { source: s.source, reframe: true, select: null, refused: 'Cannot open the link' })) linkedExaggeration = null;
    } catch (e) {
      notice.show(`${e instanceof Error ? e.message : String(e)}. Your points are unchanged.`);
    }
  });

  if (initial.message) notice.show(initial.message);
  solve(false);
  urlSync.changed();

  /** Click (without dragging) on the 3D terrain selects the nearest point. */
  function pickIn3d(): void {
    const canvas = viewer.renderer.domElement;
    let down: { x: number; y: number } | null = null;
    canvas.addEventListener('pointerdown', (e) => (down = { x: e.clientX, y: e.clientY }));
    canvas.addEventListener('pointerup', (e) => {
      if (!down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
      const r = canvas.getBoundingClientRect();
      const ndc = { x: ((e.clientX - r.left) / r.width) * 2 - 1, y: -((e.clientY - r.top) / r.height) * 2 + 1 };
      select(scene.pick(new Vector2(ndc.x, ndc.y), viewer.camera));
    });
  }

  function hooks(): void {
    publishHooks({
      ready: shown !== null,
      points: shown ? shown.points.length / 3 : 0,
      triangles: shown ? shown.triangles.length / 3 : 0,
      quads: shown ? shown.quads.length / 4 : 0,
      flipped: shown ? countFlipped(shown.choice) : 0,
      solving,
      solves,
      objective: settings.objective,
      method: settings.method,
      order: settings.order,
      exaggeration: scene.frame?.exaggeration ?? null,
      maxEdge: settings.maxEdge,
      outsideTriangles: shown ? shown.inside.reduce((n, v) => n + (v === 0 ? 1 : 0), 0) : 0,
      usefulEdges: objectivePanel.showUseful && useful ? useful.edges.length / 2 : null,
      solution: solution ? JSON.parse(solutionToJson(solution)) : null,
      choice: shown ? Array.from(shown.choice).join('') : '',
      selected,
      get notice() {
        return byId('notice').hidden ? null : byId('notice-text').textContent;
      },
      pointsCsv: () => pointsToCsv(points),
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
      point: (i) => pointAt(points, i),
      link: () => urlSync.link(),
    });
  }

  /** The state from the URL hash, or the default terrain (with a message if the
   * hash could not be used). */
  function readInitialState(): SharedState & { built: Ready; message: string | null } {
    let message: string | null = null;
    try {
      const s = decodeState(location.hash);
      if (s) {
        const built = buildTerrain(hodt, s.points, s.maxEdge);
        if (built.ok) return { ...s, built, message };
        message = `The link's points are not a valid terrain: ${built.message}. Showing the default terrain instead.`;
      }
    } catch (e) {
      if (!(e instanceof LinkError)) throw e;
      message = `${e.message[0]!.toUpperCase()}${e.message.slice(1)}. Showing the default terrain instead.`;
    }
    const pts = TERRAINS[DEFAULT_SOURCE.kind].make(DEFAULT_SOURCE.count, DEFAULT_SOURCE.seed);
    const built = buildTerrain(hodt, pts, DEFAULT_SETTINGS.maxEdge);
    if (!built.ok) throw new Error(`the default terrain failed: ${built.message}`);
    return { points: pts, ...DEFAULT_SETTINGS, view: 'split', source: DEFAULT_SOURCE, exaggeration: null, built, message };
  }
}

function settingsOf(s: SharedState): SolveSettings {
  return { objective: s.objective, method: s.method, epsilon: s.epsilon, order: s.order, maxEdge: s.maxEdge };
}
