// The "All triangulations" view (the paper's Section 1): every first order
// triangulation of a small terrain as a thumbnail, sorted by the sidebar's
// objective, the optimum first.
import { h } from '../../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../../ui/objectiveHelp.ts';
import { EDGE_COLORS, FLIPPED_COLOR, VERTEX_COLORS } from '../../views/palette.ts';
import { button, createPane, legend, paperLink, smallTerrain } from '../common.ts';
import { pageView, teachView } from '../view.ts';
import { drawThumb } from './draw.ts';
import { bruteHooks, popcount, rankTerrain, thumbSize, valueCounts, type BruteState } from './model.ts';

export const bruteView = teachView({
  id: 'brute',
  label: 'All triangulations',
  create(ctx) {
    const { root, side, main, caption } = createPane('brute', 'All first order triangulations', [
      'With m flippable quads there are 2',
      h('sup', {}, 'm'),
      ' first order Delaunay triangulations: one per choice of diagonal in each quad. For a small terrain they can all be drawn. ',
      'Here they are sorted by the objective chosen in the sidebar, best first; the optimum (gold) is what every method of the library must find. Amber quads are flipped; edges and points are coloured as in the plan view (red convex, blue reflex, purple mixed). See ',
      paperLink('1'),
      ' for the definitions and Table 1 for which objectives are easy.',
    ]);
    const status = h('p', { class: 'teach-status', id: 'brute-status', 'aria-live': 'polite' });
    const small = button('brute-small', 'Load a small terrain', 'Load a random terrain with 7 flippable quads (128 triangulations)', () =>
      ctx.load(smallTerrain(ctx.hodt, 16, 7, 7, 11), 'load a small terrain'),
    );
    const histogram = h('div', { class: 'brute-histogram', id: 'brute-histogram' });
    side.append(
      status,
      h('div', { class: 'buttons' }, small),
      histogram,
      legend([
        ['fill', FLIPPED_COLOR, 'a quad using its other diagonal (amber); teal: its Delaunay diagonal'],
        ['line', EDGE_COLORS.convex, 'convex edge; blue reflex, grey flat, dark the hull'],
        ['dot', VERTEX_COLORS.mixed, 'vertex by class (the page’s colours); large dark blue / dark red: a pit / a peak'],
        ['fill', '#d4a017', 'gold frame: an optimal triangulation (the cards are sorted, best first)'],
      ]),
    );
    const grid = h('div', { class: 'brute-grid', id: 'brute-grid' });
    main.classList.add('scroll');
    caption.hidden = true;
    main.append(grid);

    let state: BruteState = { model: null, message: null };
    let drawToken = 0;

    function refresh(): void {
      const { objective } = ctx.settings();
      const info = ctx.hodt.objectives.find((o) => o.id === objective)!;
      state = rankTerrain(ctx.terrain(), objective, info.sense);
      render();
    }

    function render(): void {
      const my = ++drawToken;
      const s = state.model;
      if (!s) {
        status.textContent = state.message ?? '';
        grid.replaceChildren();
        histogram.replaceChildren();
        return;
      }
      const m = s.structure.m;
      const optimal = s.order.filter((x) => x.value === s.best).length;
      const fmt = (v: number) => formatValue(s.objective, v);
      status.replaceChildren(
        `${m} flippable quads: ${(1 << m).toLocaleString('en')} triangulations, sorted by `,
        h('b', {}, OBJECTIVE_HELP[s.objective].name.toLowerCase()),
        ` (${s.sense === 'min' ? 'smallest' : 'largest'} first). Best value `,
        h('b', { id: 'brute-best', 'data-value': String(s.best) }, fmt(s.best)),
        `, reached by ${optimal} of them; Delaunay (no flips) has ${fmt(s.order.find((x) => x.mask === 0)!.value)}.`,
      );
      // How the values spread: one bar per distinct value.
      const distinct = valueCounts(s.order);
      const top = Math.max(...distinct.map(([, c]) => c));
      histogram.replaceChildren(
        h('span', { class: 'muted' }, 'values, best first'),
        h(
          'div',
          { class: 'bars' },
          ...distinct.slice(0, 40).map(([v, c], i) => h('i', { style: `height: ${Math.max(4, (c / top) * 48)}px`, class: i === 0 ? 'best' : '', title: `${fmt(v)}: ${c} triangulation${c === 1 ? '' : 's'}` })),
        ),
      );
      const size = thumbSize(m);
      const cards = s.order.map((x, i) => {
        const canvas = h('canvas', { width: size * 2, height: size * 2, style: `width: ${size}px; height: ${size}px` });
        const flips = popcount(x.mask);
        return h(
          'figure',
          { class: `thumb${x.value === s.best ? ' optimal' : ''}${x.mask === 0 ? ' delaunay' : ''}`, 'data-value': String(x.value), 'data-choice': String(x.mask), title: `choice ${x.mask.toString(2).padStart(m, '0')}: ${flips} flip${flips === 1 ? '' : 's'}` },
          canvas,
          h('figcaption', {}, h('b', {}, fmt(x.value)), i === 0 ? ' · best' : x.mask === 0 ? ' · Delaunay' : ''),
        );
      });
      grid.replaceChildren(...cards);
      // Draw in slices so a thousand thumbnails do not freeze the page.
      let next = 0;
      const slice = () => {
        if (my !== drawToken || s.terrain.disposed) return;
        const end = Math.min(cards.length, next + 64);
        for (; next < end; next++) drawThumb(cards[next]!.querySelector('canvas')!, s.terrain, s.structure, s.order[next]!.mask);
        if (next < cards.length) requestAnimationFrame(slice);
        else grid.dataset.drawn = String(cards.length);
      };
      delete grid.dataset.drawn;
      requestAnimationFrame(slice);
    }

    return pageView({ root, refresh, hooks: () => bruteHooks(state, Number(grid.dataset.drawn ?? 0)) });
  },
});
