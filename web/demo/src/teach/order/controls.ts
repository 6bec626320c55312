// The Order k view (the paper's Section 4.3): stepping k from 1 to 8 shows
// regions merge and, for local minima, pits disappear; the view draws what the
// library's explanation returned.
import { OBJECTIVE_IDS, type ObjectiveId } from 'hodt';
import { countRegions, describeRegions } from '../../app/regionCount.ts';
import { MAX_ORDER } from '../../app/settings.ts';
import { h } from '../../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../../ui/objectiveHelp.ts';
import { FLIPPED_COLOR } from '../../views/palette.ts';
import { createShownState } from '../canvas.ts';
import { COMPONENT_COLORS, createPane, legend, objectiveSelect, paperLink, stepControls } from '../common.ts';
import { latestSolve, pageView, teachView } from '../view.ts';
import { drawRegions, FIXED_COLOR, MINIMUM_COLOR } from './draw.ts';
import { captionText, orderHooks, startSolve, valueOf, valueRows, withOutcome, type OrderState, type OrderValue } from './model.ts';

export const orderView = teachView({
  id: 'order',
  label: 'Order k',
  create(ctx) {
    const { root, side, main, caption } = createPane('order', 'Order k: regions and fixed edges', [
      'A triangulation is k-th order Delaunay if every triangle’s circumcircle holds at most k points. An edge is useful if some such triangulation uses it. ',
      'A useful edge that no other useful edge crosses is in every one of them (fixed, dark); the fixed edges cut the hull into regions (colours), each triangulated independently, ',
      'so the library optimises region by region (the number in a region: how many k-OD triangulations it has). As k grows, regions merge and the optimum can only improve. See ',
      paperLink('4.3'),
      '.',
    ]);
    const objective = objectiveSelect(ctx, 'order-objective', OBJECTIVE_IDS, 'Objective', () => view.invalidate());
    const { player, counter, controls } = stepControls('order', {
      // Positions 0..7 are the orders 1..8.
      last: () => MAX_ORDER - 1,
      step: () => view.invalidate(),
      intervalMs: 2200,
      first: ['k = 1', 'First order'],
      prev: ['◀ k − 1', 'Lower order'],
      next: ['k + 1 ▶', 'Higher order'],
      play: 'Step k from 1 to 8',
    });
    const status = h('p', { class: 'teach-status', id: 'order-status', 'aria-live': 'polite' });
    const table = h('table', { class: 'teach-table', id: 'order-table' });
    const key = legend([
      ['line', FIXED_COLOR, 'fixed edge: in every k-OD triangulation'],
      ['dash', '#8a9691', 'useful edge that is not fixed'],
      ['fill', COMPONENT_COLORS[0]!, 'a region with a choice; its number: its k-OD triangulations (≥: at least, the count was not finished)'],
      ['fill', '#d5dad7', 'triangles with no choice at this k'],
      ['line', FLIPPED_COLOR, 'edge of the optimum that is not a Delaunay edge'],
      ['dot', MINIMUM_COLOR, 'local minimum of the optimum (a ring: one of Delaunay’s, gone at this k)'],
    ]);
    side.append(h('div', { class: 'row' }, objective), controls, status, table, key);
    const shown = createShownState<OrderState | null>(main, 'Regions of order k, fixed and useful edges, and the optimal triangulation', (c, f, s) => drawRegions(c, f, s, ctx.points()), fill, null);
    const solver = latestSolve(ctx.solver);
    /** Value per order for the current terrain and settings (the table; cleared on any change). */
    const values = new Map<number, OrderValue>();

    function refresh(): void {
      const order = player.pos + 1;
      const id = objective.value as ObjectiveId;
      const { method, epsilon, maxEdge } = ctx.settings();
      const solving = startSolve(order, id);
      shown.canvas.fit(ctx.points());
      shown.set(solving);
      solver.solve({ points: ctx.points(), objective: id, method, epsilon, order, maxEdge, explain: true }, (o) => {
        const solved = withOutcome(solving, o, ctx.terrain());
        if (solved.explanation) values.set(order, valueOf(solved.explanation.solution));
        shown.set(solved);
      });
    }

    /** The pane for the order solved (or being solved), and the values seen so far. */
    function fill(s: OrderState): void {
      const fmt = (v: number) => formatValue(s.objective, v);
      counter.textContent = `k = ${s.order}`;
      const e = s.explanation;
      const r = e?.regions ?? null;
      const count = r ? countRegions(r) : null;
      caption.textContent = captionText(s);
      if (!e) {
        status.textContent = s.failure ? `The library could not solve at order ${s.order}: ${s.failure}` : `Solving at order ${s.order}…`;
      } else if (r && count) {
        const sol = e.solution;
        status.replaceChildren(
          h('b', {}, `k = ${s.order}: `),
          `${r.useful.length / 2} useful edges, ${r.fixed.length / 2} of them fixed; ${describeRegions(count)}. `,
          `${OBJECTIVE_HELP[s.objective].name}: Delaunay ${fmt(sol.delaunayValue)}, `,
          h('b', { id: 'order-value', 'data-value': String(sol.value) }, fmt(sol.value)),
          sol.optimal ? ' (proven optimal)' : sol.bound !== null ? ` (the optimum is within ${fmt(sol.bound)})` : '',
          '.',
        );
      }
      // Value against k, for the orders seen so far.
      const rows = valueRows(values);
      table.replaceChildren(
        h('thead', {}, h('tr', {}, h('th', {}, 'k'), h('th', {}, 'Delaunay'), h('th', {}, 'value'), h('th', {}, 'proof'))),
        h(
          'tbody',
          {},
          ...rows.map(([k, v]) =>
            h('tr', { class: k === s.order ? 'current' : '' }, h('td', {}, String(k)), h('td', {}, fmt(v.delaunay)), h('td', {}, fmt(v.value)), h('td', {}, v.optimal ? 'optimal' : v.bound !== null ? `bound ${fmt(v.bound)}` : '—')),
          ),
        ),
      );
      table.hidden = rows.length === 0;
    }

    const view = pageView({
      root,
      follow: () => (objective.value = ctx.settings().objective),
      refresh,
      changed: () => values.clear(),
      canvas: shown.canvas,
      player,
      hooks: () => orderHooks(shown.state, caption.textContent),
    });
    return view;
  },
});
