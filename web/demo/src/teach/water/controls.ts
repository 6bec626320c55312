// The Water view (issue 60): where water runs on the Delaunay triangulation and
// on an optimum, so that basins visibly merge when the optimum removes pits.
import { OBJECTIVE_IDS, type ObjectiveId } from 'hodt';
import { h } from '../../ui/dom.ts';
import { OBJECTIVE_HELP } from '../../ui/objectiveHelp.ts';
import { orderOptions } from '../../ui/orderOptions.ts';
import { createShownState } from '../canvas.ts';
import { button, COMPONENT_COLORS, createPane, legend, objectiveOptions, paperLink } from '../common.ts';
import { latestSolve, pageView, teachView } from '../view.ts';
import { drawWater, FLOW_COLOR, OUTLET_COLOR, PIT_COLOR } from './draw.ts';
import { countsText, shownNetwork, startWater, waterHooks, withSolution, type WaterShown, type WaterState } from './model.ts';

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

    let showing: WaterShown = 'optimum';
    const show = (which: WaterShown) => {
      showing = which;
      for (const [b, w] of [[delaunayButton, 'delaunay'], [optimumButton, 'optimum']] as const) b.setAttribute('aria-pressed', String(w === which));
      shown.render();
    };
    const delaunayButton = button('water-show-delaunay', 'Delaunay', 'Show the drainage of the Delaunay triangulation', () => show('delaunay'));
    const optimumButton = button('water-show-optimum', 'Optimum', 'Show the drainage of the optimal triangulation', () => show('optimum'));

    const counts = h('p', { class: 'teach-status', id: 'water-counts', 'aria-live': 'polite' });
    const why = h(
      'p',
      { class: 'teach-note', id: 'water-why' },
      'Why pits matter: water stops at every pit, so a pit that is only an artefact of the triangulation cuts its basin off from the stream it belongs to. With fewer pits, basins merge and the flow lines join into longer streams.',
    );
    const key = legend([
      ['line', FLOW_COLOR, 'flow: each point to its steepest lower neighbour; wider with log(points draining through it)'],
      ['fill', COMPONENT_COLORS[0]!, 'a basin (the points that end at one pit or outlet); a triangle takes the basin of two of its corners, pale if none'],
      ['dot', PIT_COLOR, 'pit: an interior point where water stops'],
      ['dot', OUTLET_COLOR, 'outlet (a square): a boundary point where water leaves'],
    ]);
    side.append(h('div', { class: 'row' }, objective, order), h('div', { class: 'segmented' }, delaunayButton, optimumButton), counts, why, key);

    const shown = createShownState<WaterState | null>(main, 'Drainage: flow lines, basins, pits and outlets', (c, f, s) => drawWater(c, f, shownNetwork(s, showing), ctx.points()), fill, null);
    const solver = latestSolve(ctx.solver);

    function refresh(): void {
      const k = Number(order.value), id = objective.value as ObjectiveId;
      const { method, epsilon, maxEdge } = ctx.settings();
      const terrain = ctx.terrain();
      const solving = startWater(terrain, k, id);
      shown.canvas.fit(ctx.points());
      shown.set(solving);
      solver.solve({ points: ctx.points(), objective: id, method, epsilon, order: k, maxEdge }, (o) => {
        if (!terrain.disposed) shown.set(withSolution(solving, o, terrain));
      });
    }

    function fill(s: WaterState): void {
      counts.textContent = countsText(s);
      const which = showing === 'optimum' && s.optimum ? `the optimum (${OBJECTIVE_HELP[s.objective].name.toLowerCase()}, order ${s.order})` : 'Delaunay';
      caption.textContent = `Drainage of ${which}`;
    }

    show(showing);
    const view = pageView({
      root,
      refresh,
      changed: () => solver.drop(),
      canvas: shown.canvas,
      hooks: () => waterHooks(shown.state, showing, counts.textContent ?? ''),
    });
    return view;
  },
});
