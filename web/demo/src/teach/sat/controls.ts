// The 2-SAT search view (the paper's Section 2.1): the bottleneck search step
// by step, as the library ran it; the view only draws what terrain.explain gave.
import type { Solution } from 'hodt';
import { jitteredGridPoints } from '../../terrains/jitteredGrid.ts';
import { h } from '../../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../../ui/objectiveHelp.ts';
import { CRITICAL_COLOR, FLIPPED_COLOR, QUAD_COLOR } from '../../views/palette.ts';
import { createShownState } from '../canvas.ts';
import { button, COMPONENT_COLORS, createPane, legend, objectiveSelect, paperLink, stepControls } from '../common.ts';
import { pageView, teachView } from '../view.ts';
import { BLOCK_COLOR, drawLine, drawSearch } from './draw.ts';
import { captionText, counterText, explainSearch, isPairObjective, lastPosition, PAIR_OBJECTIVES, quadPairs, satHooks, testAt, type PairObjective, type SatState } from './model.ts';

export const satView = teachView({
  id: 'sat',
  label: '2-SAT search',
  create(ctx) {
    const { root, side, main, caption } = createPane('sat', '2-SAT search for min-max objectives', [
      'A min-max objective is the worst value over pairs of adjacent triangles. Only a few values can be the optimum: the candidates on the line below. ',
      'The solver asks, by binary search (the lower bound first: it is often the optimum): "is there a first order triangulation with every pair at most t?" ',
      'Pairs of fixed triangles over t answer no at once; a quad with one diagonal over t is forced to the other; every remaining pair over t between two quads becomes 2-SAT clauses on their diagonals, ',
      'solved through the strongly connected components of the implication graph. See ',
      paperLink('2.1'),
      '.',
    ]);
    const objective = objectiveSelect(ctx, 'sat-objective', PAIR_OBJECTIVES, 'Pair objective', () => view.invalidate());
    // A jittered grid: its many adjacent quads give 2-SAT instances with clauses
    // between quads and answers "no" found by the components, not only at once.
    const example = jitteredGridPoints(64, 15);
    const gridSide = Math.round(Math.sqrt(example.length / 3));
    const small = button('sat-small', 'Example', `Load a ${example.length / 3}-point jittered grid (${gridSide} x ${gridSide}, seed 15) whose search has clauses between quads`, () =>
      ctx.load(example, 'load the 2-SAT example', objective.value as PairObjective, { kind: 'grid', count: example.length / 3, seed: 15 }),
    );
    const line = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
    line.setAttribute('class', 'sat-line');
    line.setAttribute('viewBox', '0 0 320 40');
    line.setAttribute('role', 'img');
    line.setAttribute('aria-label', 'Candidate values and tested thresholds');
    const status = h('p', { class: 'teach-status', id: 'sat-status', 'aria-live': 'polite' });
    const list = h('ol', { class: 'sat-steps', id: 'sat-steps' });
    const { player, counter, controls } = stepControls('sat', {
      last: () => lastPosition(shown.state.search),
      step: () => shown.render(),
      intervalMs: 1300,
      first: ['Start', 'Back to the start'],
      prev: ['◀ Prev', 'Previous step'],
      next: ['Next ▶', 'Next step'],
      play: 'Step through the search',
    });
    const key = legend([
      ['fill', QUAD_COLOR, 'forced to keep its Delaunay diagonal'],
      ['fill', FLIPPED_COLOR, 'forced (or chosen) to flip'],
      ['fill', BLOCK_COLOR, 'both diagonals over t: no'],
      ['line', '#4d5753', 'clauses between two quads: each diagonal implies one of the other’s (arrows both ways)'],
      ['dot', COMPONENT_COLORS[0]!, 'quads whose diagonals lie in one strongly connected component share a colour'],
      ['cross', BLOCK_COLOR, 'both diagonals of a quad in one component: unsatisfiable'],
      ['fill', CRITICAL_COLOR, 'at the end: the worst pair of triangles (the optimum)'],
      ['line', '#1f77b4', 'number line: the interval still searched (blue), thresholds answered yes (green) and no (red)'],
    ]);
    side.append(h('div', { class: 'row' }, objective, small), line, controls, status, list, key);
    const shown = createShownState<SatState>(main, '2-SAT step: the terrain, forced quads, pairs over the threshold and the implication graph', (c, f, s) => s.search && drawSearch(c, f, s.search, player.pos), fill, { search: null, error: null });

    /** The sidebar's objective, when it is one this view shows. */
    function follow(): void {
      const page = ctx.settings().objective;
      if (isPairObjective(page)) objective.value = page;
    }

    function refresh(): void {
      player.stop();
      const state = explainSearch(ctx.terrain(), objective.value as PairObjective);
      if (state.search) shown.canvas.fit(state.search.structure.points);
      player.pos = 0;
      shown.set(state);
    }

    /** The pane for the current step of the search, or why there is none. */
    function fill(state: SatState): void {
      if (!state.search) {
        status.textContent = state.error ? `Cannot show the search: ${state.error}` : '';
        list.replaceChildren();
        line.replaceChildren();
        counter.textContent = '';
        return;
      }
      const s = state.search;
      const id = s.objective;
      const fmt = (v: number) => formatValue(id, v);
      const n = s.search.tests.length;
      counter.textContent = counterText(s, player.pos);
      caption.textContent = captionText(s, player.pos, fmt);
      // The step list.
      list.replaceChildren(
        ...s.search.tests.map((t, i) => {
          const li = h(
            'li',
            { class: `${t.satisfiable ? 'yes' : 'no'}${i + 1 === player.pos ? ' current' : ''}`, 'data-threshold': String(t.threshold) },
            h('b', {}, `t = ${fmt(t.threshold)}`),
            ` ${t.satisfiable ? '✓ yes' : '✗ no'}`,
            h('span', { class: 'muted' }, t.immediateNo ? ' · immediate no' : ` · ${t.clauses.length / 2} clause${t.clauses.length === 2 ? '' : 's'} · ${t.forced.length / 2} forced`),
          );
          li.addEventListener('click', () => player.go(i + 1));
          return li;
        }),
      );
      drawLine(line, s, player.pos);
      // What the current step means.
      const measure = OBJECTIVE_HELP[id].measure.toLowerCase().replace(/^worst /, '');
      if (n === 0) {
        status.replaceChildren(
          `Nothing to search: the lower bound equals the Delaunay value, so every first order triangulation has ${measure} `,
          final(s.solution),
          '.',
        );
      } else if (player.pos === 0) {
        status.replaceChildren(
          `${s.search.candidates.length} candidate values lie between the lower bound (${fmt(s.search.candidates[0]!)}) and the Delaunay value (${fmt(s.solution.delaunayValue)}). `,
          `The search tests the lower bound first, then halves the rest: ${n} test${n === 1 ? '' : 's'} in all. Press Next.`,
        );
      } else if (player.pos <= n) {
        const a = testAt(s, player.pos)!;
        const parts: (string | Node)[] = [h('b', {}, `Is there a triangulation with ${measure} ≤ ${fmt(a.threshold)}? `)];
        const forced = a.forced.length / 2, pairs = quadPairs(a).length;
        if (a.immediateNo && a.blocked.length === 0) parts.push(`A pair of fixed triangles measures ${fmt(s.search.floor)}, over it: no, immediately. `);
        else if (a.immediateNo) parts.push(`Quad ${a.blocked[0]} has both diagonals over it: no, immediately. `);
        else {
          parts.push(
            `${forced} quad${forced === 1 ? ' is' : 's are'} forced, ${pairs} pair${pairs === 1 ? '' : 's'} of quads constrain each other (${a.clauses.length / 2} clauses in all). `,
            a.satisfiable
              ? 'The implication graph has no quad whose two diagonals are in one strongly connected component: yes, satisfiable (the diagonals shown). '
              : `${a.conflicts.length} quad${a.conflicts.length === 1 ? ' has' : 's have'} both diagonals in one strongly connected component (✕): no. `,
          );
        }
        parts.push(a.satisfiable ? 'The optimum is at most t: search below.' : 'The optimum is above t: search above.');
        status.replaceChildren(...parts);
      } else {
        status.replaceChildren(
          'Done: the optimum is ',
          final(s.solution),
          `, the smallest candidate with answer yes (Delaunay: ${fmt(s.solution.delaunayValue)}). The flipped quads of the optimal triangulation are amber.`,
        );
      }
    }

    function final(sol: Solution): HTMLElement {
      return h('b', { id: 'sat-final', 'data-value': String(sol.value) }, formatValue(sol.objective, sol.value));
    }

    const view = pageView({
      root,
      follow,
      refresh,
      canvas: shown.canvas,
      player,
      hooks: () => satHooks(shown.state, objective.value, player.pos),
    });
    return view;
  },
});
