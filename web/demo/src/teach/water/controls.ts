// The Water view (issue 60): where water runs on the Delaunay triangulation and
// on an optimum, side by side, so that basins visibly merge when the optimum
// removes pits; or one of them alone, for narrow screens.
import { OBJECTIVE_IDS, type ObjectiveId } from 'hodt';
import { h } from '../../ui/dom.ts';
import { OBJECTIVE_HELP } from '../../ui/objectiveHelp.ts';
import { orderOptions } from '../../ui/orderOptions.ts';
import { createFittedCanvas } from '../canvas.ts';
import { button, createPane, legend, objectiveOptions, paperLink } from '../common.ts';
import { latestSolve, pageView, teachView } from '../view.ts';
import { drawWater } from './draw.ts';
import { countsText, networkFor, sideCounts, sidesOf, startWater, waterHooks, withSolution, type WaterLayout, type WaterSide, type WaterState } from './model.ts';
import { BASIN_COLORS, FLOW_COLOR, OUTLET_COLOR, PIT_COLOR } from './waterStyle.js';

/** Removing pits is what the paper optimises for water: the view starts there. */
const DEFAULT_OBJECTIVE: ObjectiveId = 'min-local-minima';

export const waterView = teachView({
  id: 'water',
  label: 'Water',
  create(ctx) {
    const { root, side, main, caption } = createPane('water', 'Water: drainage and pits', [
      'Water at a point runs down the edge to its steepest lower neighbour; the library follows it exactly. ',
      'It stops at a pit (an interior point with no lower neighbour) or leaves at an outlet on the boundary, and the points that end at the same place form a basin. ',
      'Runoff and erosion models break at pits the triangulation made up: choosing the diagonals for the fewest local minima removes them, and their basins merge into their neighbours’. See ',
      paperLink('1'),
      '.',
    ]);
    // The view's own objective: the sidebar's may be any, the water view starts at the fewest pits.
    const objective = objectiveOptions('water-objective', OBJECTIVE_IDS, 'Objective of the optimum');
    objective.value = DEFAULT_OBJECTIVE;
    const order = h('select', { id: 'water-order', 'aria-label': 'Order k of the optimum' });
    order.replaceChildren(...orderOptions());
    for (const select of [objective, order]) select.addEventListener('change', () => view.invalidate());

    let state: WaterState | null = null;
    // One pane per side, each with its caption (name and counts) and canvas;
    // each pane captions itself, so the view's own caption goes.
    caption.remove();
    const panes = (['delaunay', 'optimum'] as const).map((which) => {
      const name = h('b', { class: 'water-name' });
      const counts = h('span', { id: `water-${which}-counts` });
      const el = h('div', { class: 'water-pane', id: `water-pane-${which}` }, h('span', { class: 'view-label', id: `water-${which}-caption` }, name, ' ', counts));
      const label = which === 'delaunay' ? 'Drainage of the Delaunay triangulation' : 'Drainage of the optimal triangulation';
      const canvas = createFittedCanvas(el, (c, f) => {
        const w = state && networkFor(state, which);
        if (w && state) drawWater(c, f, w, ctx.points(), state.slots);
      }, label);
      return { which, el, name, counts, canvas };
    });
    const split = h('div', { class: 'water-panes' }, ...panes.map((p) => p.el));
    main.append(split);

    let layout: WaterLayout = 'both';
    const layoutButtons = ([
      ['both', 'Side by side', 'Show the drainage of Delaunay and of the optimum side by side'],
      ['delaunay', 'Delaunay', 'Show the drainage of the Delaunay triangulation alone'],
      ['optimum', 'Optimum', 'Show the drainage of the optimal triangulation alone'],
    ] as const).map(([which, text, title]) => button(`water-show-${which}`, text, title, () => show(which)));
    const show = (which: WaterLayout) => {
      layout = which;
      layoutButtons.forEach((b, i) => b.setAttribute('aria-pressed', String((['both', 'delaunay', 'optimum'] as const)[i] === which)));
      split.dataset.layout = which;
      for (const p of panes) p.el.hidden = !sidesOf(which).includes(p.which);
      render();
    };

    const counts = h('p', { class: 'teach-status', id: 'water-counts', 'aria-live': 'polite' });
    const why = h(
      'p',
      { class: 'teach-note', id: 'water-why' },
      'Why pits matter: water stops at every pit, so a pit that is only an artefact of the triangulation cuts its basin off from the stream it belongs to. With fewer pits, basins merge and the flow lines join into longer streams.',
    );
    const key = legend([
      ['line', FLOW_COLOR, 'flow: each point to its steepest lower neighbour; wider with log(points draining through it)'],
      ['fill', BASIN_COLORS[0], 'a basin (the points that end at one pit or outlet), in the colour of its Delaunay basin: a merged basin takes the colour of the one it joined; a triangle takes the basin of two of its corners, pale if none'],
      ['dot', PIT_COLOR, 'pit: an interior point where water stops'],
      ['dot', OUTLET_COLOR, 'outlet (a square): a boundary point where water leaves'],
    ]);
    side.append(h('div', { class: 'row' }, objective, order), h('div', { class: 'segmented' }, ...layoutButtons), counts, why, key);

    /** The panes' captions and the counts, from the state; the canvases redrawn. */
    function render(): void {
      for (const p of panes) p.canvas.redraw();
      if (!state) return;
      counts.textContent = countsText(state);
      for (const p of panes) {
        // Short, so that the counts fit beside it: the objective is the select's, and the canvas's label.
        p.name.textContent = p.which === 'delaunay' ? 'Delaunay' : `Optimum (order ${state.order})`;
        if (p.which === 'optimum') p.canvas.canvas.setAttribute('aria-label', `Drainage of the optimal triangulation (${OBJECTIVE_HELP[state.objective].name.toLowerCase()}, order ${state.order})`);
        p.counts.textContent = sideCounts(state, p.which);
      }
    }
    const set = (s: WaterState) => {
      state = s;
      render();
    };
    const solver = latestSolve(ctx.solver);

    function refresh(): void {
      const k = Number(order.value), id = objective.value as ObjectiveId;
      const { method, epsilon, maxEdge } = ctx.settings();
      const terrain = ctx.terrain();
      const solving = startWater(terrain, k, id);
      for (const p of panes) p.canvas.fit(ctx.points());
      set(solving);
      solver.solve({ points: ctx.points(), objective: id, method, epsilon, order: k, maxEdge }, (o) => {
        if (!terrain.disposed) set(withSolution(solving, o, terrain));
      });
    }

    show(layout);
    const paneText = () => Object.fromEntries(panes.map((p) => [p.which, p.el.querySelector('.view-label')!.textContent ?? ''])) as Record<WaterSide, string>;
    const view = pageView({
      root,
      refresh,
      changed: () => solver.drop(),
      canvas: { redraw: () => panes.forEach((p) => p.canvas.redraw()) },
      hooks: () => waterHooks(state, layout, counts.textContent ?? '', paneText()),
    });
    return view;
  },
});
