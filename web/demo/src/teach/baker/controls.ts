// The Baker layers view (the paper's Section 4): the layering of Baker's scheme
// for the NP-hard objectives as the library's run recorded it (terrain.explain);
// the view only draws it.
import { h } from '../../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../../ui/objectiveHelp.ts';
import { FLIPPED_COLOR } from '../../views/palette.ts';
import { createShownState, layerColor } from '../canvas.ts';
import { createPane, legend, objectiveOptions, paperLink, stepControls } from '../common.ts';
import { readStructure } from '../structure.ts';
import { latestSolve, pageView, teachView } from '../view.ts';
import { CUT_COLOR, drawLayers } from './draw.ts';
import {
  BAKER_OBJECTIVES,
  bakerHooks,
  bestShift,
  bestValue,
  captionText,
  clampEpsilon,
  counterText,
  cutsOf,
  isMax,
  lastPosition,
  shiftsOf,
  startRun,
  tightestBound,
  withOutcome,
  type BakerObjective,
  type BakerState,
} from './model.ts';

export const bakerView = teachView({
  id: 'baker',
  label: 'Baker layers',
  create(ctx) {
    const { root, side, main, caption } = createPane('baker', 'Baker’s layers for NP-hard objectives', [
      'Most convex edges and fewest mixed vertices are NP-hard, but the quads form a planar graph (dots: a quad each, joined when two quads share an edge). ',
      'Peeling it from the hull gives layers (colours). For each shift i < λ = ⌈1/ε⌉, cutting the edges between layers l and l + 1 for every l ≡ i (mod λ) leaves thick layers of small treewidth, each solved exactly; ',
      'some shift loses at most a 1/λ share of the optimum, so the best shift is within (1 − ε) of it, and each shift’s relaxed optimum plus what it cut bounds the optimum from above. See ',
      paperLink('4'),
      ' (4.1 for convex edges).',
    ]);
    const objective = objectiveOptions('baker-objective', BAKER_OBJECTIVES, 'Objective');
    const epsilon = h('input', { id: 'baker-epsilon', type: 'number', min: 0.05, max: 0.95, step: 0.05, value: 0.34, 'aria-label': 'epsilon' });
    const lambdaOut = h('span', { class: 'teach-counter', id: 'baker-lambda' });
    for (const el of [objective, epsilon]) {
      el.addEventListener('change', () =>
        // The sidebar follows the view's objective and epsilon.
        view.invalidate(() => ctx.choose({ objective: objective.value as BakerObjective, epsilon: clampEpsilon(epsilon.value) })),
      );
    }
    const { player, counter, controls } = stepControls('baker', {
      last: () => lastPosition(shown.state),
      step: () => shown.render(),
      intervalMs: 1400,
      first: ['Start', 'Layers only'],
      prev: ['◀ Prev', 'Previous shift'],
      next: ['Next ▶', 'Next shift'],
      play: 'Step through the shifts',
    });
    const status = h('p', { class: 'teach-status', id: 'baker-status', 'aria-live': 'polite' });
    const table = h('table', { class: 'teach-table', id: 'baker-table' });
    const libraryLine = h('p', { class: 'teach-note', id: 'baker-library' });
    const layerKey = h('div', { class: 'layer-key', id: 'baker-layers' });
    side.append(
      h('div', { class: 'row' }, objective),
      h('div', { class: 'row' }, h('label', { for: 'baker-epsilon' }, 'ε'), epsilon, lambdaOut),
      controls,
      status,
      table,
      libraryLine,
      layerKey,
      legend([
        ['dot', layerColor(0, 2), 'a quad, coloured by its layer (key above: hull side first)'],
        ['line', 'rgba(30, 42, 38, 0.55)', 'two quads sharing an edge (a term of the objective joins them)'],
        ['dash', CUT_COLOR, 'cut by this shift: the terms across it are dropped'],
        ['line', FLIPPED_COLOR, 'outline: a quad this shift’s (or the result’s) triangulation flips'],
      ]),
    );
    const shown = createShownState<BakerState | null>(main, 'Quad graph coloured by layer, with the edges cut by the current shift', (c, f, s) => drawLayers(c, f, s, player.pos), fill, null);
    const solver = latestSolve(ctx.solver);

    /** The sidebar's objective (when this view shows it) and epsilon. */
    function follow(): void {
      const page = ctx.settings();
      if ((BAKER_OBJECTIVES as readonly string[]).includes(page.objective)) objective.value = page.objective;
      epsilon.value = String(page.epsilon);
    }

    function refresh(): void {
      player.stop();
      const eps = clampEpsilon(epsilon.value);
      const id = objective.value as BakerObjective;
      const run = startRun(readStructure(ctx.terrain()), id, eps);
      player.pos = 0;
      shown.canvas.fit(run.structure.points);
      shown.set(run);
      // In the teaching views' worker (the page stays responsive while it runs).
      solver.solve({ points: ctx.points(), objective: id, method: 'approx', epsilon: eps, order: 1, maxEdge: ctx.settings().maxEdge, explain: true }, (o) => shown.set(withOutcome(run, o)));
    }

    /** The pane for the current position of the player. */
    function fill(s: BakerState): void {
      const fmt = (v: number) => formatValue(s.objective, v);
      const max = isMax(s);
      const shifts = shiftsOf(s);
      lambdaOut.textContent = s.lambda ? `λ = ${s.lambda}` : 'λ = …';
      lambdaOut.title = `⌈1/ε⌉ = ${Math.ceil(1 / s.epsilon - 1e-9)}; the library takes λ = ⌈span/ε⌉ where span is the most layers one of its terms straddles`;
      counter.textContent = counterText(s, player.pos);
      caption.textContent = captionText(s, player.pos);
      layerKey.replaceChildren(
        h('span', { class: 'muted' }, 'layer '),
        ...Array.from({ length: s.layers }, (_, l) => h('i', { style: `background: ${layerColor(l, s.layers)}`, title: `layer ${l}` }, String(l))),
      );
      // Per-shift table.
      const rows = shifts.map((x, i) => {
        const tr = h(
          'tr',
          { class: i + 1 === player.pos ? 'current' : '', 'data-shift': String(i) },
          h('td', {}, String(i)),
          h('td', {}, String(x.dropped)),
          h('td', {}, fmt(x.relaxed)),
          h('td', {}, fmt(x.value)),
          h('td', {}, fmt(x.bound)),
        );
        tr.addEventListener('click', () => player.go(i + 1));
        return tr;
      });
      if (shifts.length) {
        const best = bestValue(s);
        const bound = tightestBound(s);
        rows.forEach((tr, i) => {
          if (shifts[i]!.value === best) tr.children[3]!.classList.add('best');
          if (shifts[i]!.bound === bound) tr.children[4]!.classList.add('best');
        });
      }
      table.replaceChildren(
        h(
          'thead',
          {},
          h(
            'tr',
            {},
            h('th', {}, 'shift'),
            h('th', { title: 'terms the cuts dropped (convex edges: edges between quads; mixed vertices: vertices whose quads straddle a cut)' }, 'cut'),
            h('th', { title: max ? 'optimum of what the shift keeps (cut terms count 0)' : 'mixed vertices if every cut vertex were mixed, at the optimum of what the shift keeps' }, 'kept opt.'),
            h('th', { title: max ? 'convex edges of that triangulation' : 'mixed vertices of that triangulation' }, 'value'),
            h('th', { title: max ? 'kept optimum + the most the cut terms could add: the optimum is at most this' : 'the fewest mixed vertices are at least this' }, 'bound'),
          ),
        ),
        h('tbody', {}, ...rows),
      );
      table.hidden = shifts.length === 0;
      // The library's result.
      if (s.solution) {
        const sol = s.solution;
        libraryLine.replaceChildren(
          'Library (approx): ',
          h('b', { id: 'baker-value', 'data-value': String(sol.value) }, fmt(sol.value)),
          sol.bound !== null ? ` · optimum ${sol.sense === 'max' ? '≤' : '≥'} ` : '',
          sol.bound !== null ? h('b', { id: 'baker-bound', 'data-value': String(sol.bound) }, fmt(sol.bound)) : ' · proven optimal',
          ` · Delaunay ${fmt(sol.delaunayValue)} · ${sol.details}${sol.localSearchImproved ? ' · local search improved the best shift' : ''}.`,
        );
      } else {
        libraryLine.textContent = s.failure ? `The library could not run the approximation: ${s.failure}` : 'Running the approximation…';
      }
      // What the current position shows.
      if (player.pos === 0) {
        status.replaceChildren(
          s.lambda ? `${s.structure.m} quads in ${s.layers} layers (depth of a quad: fewest Delaunay edges from the hull to one of its corners). Press Next for the shifts.` : `${s.structure.m} quads.`,
        );
      } else if (s.lambda && player.pos <= s.lambda) {
        const i = player.pos - 1;
        const cuts = cutsOf(i, s.layers, s.lambda);
        const x = shifts[i]!;
        status.replaceChildren(
          h('b', {}, `Shift ${i}: `),
          cuts.length ? `cut between layers ${cuts.map((l) => `${l}|${l + 1}`).join(', ')} (red dashes). ` : 'no cut falls inside this terrain’s layers. ',
          max
            ? `The thick layers' optimum keeps ${fmt(x.relaxed)}; its triangulation (amber flips) has ${fmt(x.value)}; the optimum is at most ${fmt(x.bound)}.`
            : `The thick layers' optimum, with every cut vertex counted as mixed, has ${fmt(x.relaxed)} mixed vertices; its triangulation (amber flips) has ${fmt(x.value)}; the fewest possible are at least ${fmt(x.bound)}.`,
        );
      } else if (s.lambda) {
        const best = bestShift(s);
        status.replaceChildren(
          h('b', { id: 'baker-done' }, 'Result: '),
          best ? `the best shift is ${best.shift} with ${fmt(best.value)}; the tightest bound is ${fmt(tightestBound(s))}. ` : '',
          s.solution ? `The library returns ${fmt(s.solution.value)} (amber flips)${s.solution.bound !== null ? `, proven within ${fmt(s.solution.bound)}` : ', proven optimal'}.` : '',
        );
      }
    }

    const view = pageView({
      root,
      follow,
      refresh,
      // A result for the old terrain must not land on the new one.
      changed: () => solver.drop(),
      canvas: shown.canvas,
      player,
      hooks: () => bakerHooks(shown.state, objective.value, player.pos),
    });
    return view;
  },
});
