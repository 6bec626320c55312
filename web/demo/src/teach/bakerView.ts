// Teaching view 2: Baker's layering for the NP-hard objectives (Section 4). The
// quads are nodes, joined when they share an edge; a quad's layer is its peeling
// depth. For each shift, the edges between layers l and l + 1 with l = shift
// (mod lambda) are cut; the thick layers left are solved exactly and the best
// shift wins. Everything shown (layers, lambda, each shift's cut, optimum,
// value, bound and triangulation) is what the library's run recorded
// (terrain.explain); this view only draws it.
import type { BakerExplanation, ObjectiveId, Solution } from 'hodt';
import { h } from '../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../ui/objectiveHelp.ts';
import { FLIPPED_COLOR } from '../views/palette.ts';
import { withAlpha } from '../views/plan/planRenderer.ts';
import { createFittedCanvas, drawBackdrop, layerColor, type FittedCanvas } from './canvas.ts';
import { createPane, legend, paperLink, stepControls, type TeachContext, type TeachView } from './common.ts';
import { readStructure, trianglesOf, type QuadStructure } from './structure.ts';
import { StepPlayer } from './stepPlayer.ts';

const OBJECTIVES = ['max-convex-edges', 'min-mixed-vertices'] as const satisfies readonly ObjectiveId[];
const CUT_COLOR = '#d62728';

interface State {
  structure: QuadStructure;
  objective: (typeof OBJECTIVES)[number];
  epsilon: number;
  /** The library's run, once it has answered. */
  baker: BakerExplanation | null;
  layers: number;
  lambda: number | null;
  solution: Solution | null;
  failure: string | null;
}

/** Does a cut of this shift (after the layers l with l mod lambda == shift)
 * separate two quads in layers lo <= hi? (Drawing only: the library decided
 * which terms each shift dropped.) */
function isCut(lo: number, hi: number, shift: number, lambda: number): boolean {
  const firstCut = lo + ((((shift - lo) % lambda) + lambda) % lambda);
  return firstCut < hi;
}

export function createBakerView(ctx: TeachContext): TeachView {
  const { root, side, main, caption } = createPane('baker', 'Baker’s layers for NP-hard objectives', [
    'Most convex edges and fewest mixed vertices are NP-hard, but the quads form a planar graph (dots: a quad each, joined when two quads share an edge). ',
    'Peeling it from the hull gives layers (colours). For each shift i < λ = ⌈1/ε⌉, cutting the edges between layers l and l + 1 for every l ≡ i (mod λ) leaves thick layers of small treewidth, each solved exactly; ',
    'some shift loses at most a 1/λ share of the optimum, so the best shift is within (1 − ε) of it, and each shift’s relaxed optimum plus what it cut bounds the optimum from above. See ',
    paperLink('4'),
    ' (4.1 for convex edges).',
  ]);
  const objective = h('select', { id: 'baker-objective', 'aria-label': 'Objective' });
  objective.replaceChildren(...OBJECTIVES.map((id) => h('option', { value: id }, OBJECTIVE_HELP[id].name)));
  const epsilon = h('input', { id: 'baker-epsilon', type: 'number', min: 0.05, max: 0.95, step: 0.05, value: 0.34, 'aria-label': 'epsilon' });
  const lambdaOut = h('span', { class: 'teach-counter', id: 'baker-lambda' });
  for (const el of [objective, epsilon]) {
    el.addEventListener('change', () => {
      stale = true;
      // The sidebar follows the view's objective and epsilon.
      ctx.choose({ objective: objective.value as State['objective'], epsilon: Math.min(0.95, Math.max(0.05, Number(epsilon.value) || 0.34)) });
      update();
    });
  }
  const player = new StepPlayer(() => last(), () => render(), 1400);
  const counter = h('span', { class: 'teach-counter', id: 'baker-counter' });
  const controls = stepControls('baker', player, counter, {
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
  const canvas = createFittedCanvas(main, (c, f) => draw(c, f), 'Quad graph coloured by layer, with the edges cut by the current shift');

  let active = false;
  let stale = true;
  let state: State | null = null;
  let token = 0;

  /** The sidebar's objective (when this view shows it) and epsilon. */
  function follow(): void {
    const page = ctx.settings();
    if ((OBJECTIVES as readonly string[]).includes(page.objective)) objective.value = page.objective;
    epsilon.value = String(page.epsilon);
  }

  function update(): void {
    if (!active || !stale) return;
    stale = false;
    player.stop();
    const my = ++token;
    const eps = Math.min(0.95, Math.max(0.05, Number(epsilon.value) || 0.34));
    const id = objective.value as State['objective'];
    const structure = readStructure(ctx.terrain());
    state = { structure, objective: id, epsilon: eps, baker: null, layers: 0, lambda: null, solution: null, failure: null };
    player.pos = 0;
    canvas.fit(structure.points);
    render();
    // In the teaching views' worker (the page stays responsive while it runs).
    void ctx.solver.solve({ points: ctx.points(), objective: id, method: 'approx', epsilon: eps, order: 1, maxEdge: ctx.settings().maxEdge, explain: true }).then((o) => {
      if (my !== token || !state) return;
      if (o.status !== 'solved') state.failure = o.status === 'failed' ? o.message : 'cancelled';
      else {
        state.solution = o.solution;
        state.baker = o.explanation?.baker ?? null;
        if (!state.baker) state.failure = `the library did not run Baker's scheme (${o.solution.details})`;
        else {
          state.lambda = state.baker.lambda;
          state.layers = state.baker.layer.reduce((a, b) => Math.max(a, b + 1), 0);
        }
      }
      render();
    });
  }

  const shifts = (s: State) => s.baker?.shifts ?? [];
  const last = () => (state?.lambda ? state.lambda + 1 : 0);

  function render(): void {
    canvas.redraw();
    const s = state;
    if (!s) return;
    const fmt = (v: number) => formatValue(s.objective, v);
    const max = s.objective === 'max-convex-edges';
    const shifts = s.baker?.shifts ?? [];
    lambdaOut.textContent = s.lambda ? `λ = ${s.lambda}` : 'λ = …';
    lambdaOut.title = `⌈1/ε⌉ = ${Math.ceil(1 / s.epsilon - 1e-9)}; the library takes λ = ⌈span/ε⌉ where span is the most layers one of its terms straddles`;
    counter.textContent = !s.lambda ? '' : player.pos === 0 ? 'layers' : player.pos > s.lambda ? 'result' : `shift ${player.pos - 1} of 0–${s.lambda - 1}`;
    caption.textContent =
      !s.lambda || player.pos === 0
        ? 'Quads by layer (peeling depth), joined when they share an edge'
        : player.pos > s.lambda
          ? 'The library’s result: flipped quads outlined amber'
          : `Shift ${player.pos - 1}: red dashes are cut · amber outlines: this shift’s flips`;
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
    const pick = (values: number[], most: boolean) => (most ? Math.max(...values) : Math.min(...values));
    if (shifts.length) {
      // Most convex edges: the best value is the largest, the bound the smallest;
      // fewest mixed vertices the other way round.
      const best = pick(shifts.map((x) => x.value), max);
      const bound = pick(shifts.map((x) => x.bound), !max);
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
      const cuts: number[] = [];
      for (let l = i; l < s.layers - 1; l += s.lambda) cuts.push(l);
      const x = shifts[i]!;
      status.replaceChildren(
        h('b', {}, `Shift ${i}: `),
        cuts.length ? `cut between layers ${cuts.map((l) => `${l}|${l + 1}`).join(', ')} (red dashes). ` : 'no cut falls inside this terrain’s layers. ',
        max
          ? `The thick layers' optimum keeps ${fmt(x.relaxed)}; its triangulation (amber flips) has ${fmt(x.value)}; the optimum is at most ${fmt(x.bound)}.`
          : `The thick layers' optimum, with every cut vertex counted as mixed, has ${fmt(x.relaxed)} mixed vertices; its triangulation (amber flips) has ${fmt(x.value)}; the fewest possible are at least ${fmt(x.bound)}.`,
      );
    } else if (s.lambda) {
      const best = shifts.length ? shifts.reduce((a, b) => ((max ? b.value > a.value : b.value < a.value) ? b : a)) : null;
      status.replaceChildren(
        h('b', { id: 'baker-done' }, 'Result: '),
        best ? `the best shift is ${best.shift} with ${fmt(best.value)}; the tightest bound is ${fmt(pick(shifts.map((x) => x.bound), !max))}. ` : '',
        s.solution ? `The library returns ${fmt(s.solution.value)} (amber flips)${s.solution.bound !== null ? `, proven within ${fmt(s.solution.bound)}` : ', proven optimal'}.` : '',
      );
    }
  }

  function draw(c: CanvasRenderingContext2D, f: FittedCanvas): void {
    const s = state;
    if (!s) return;
    const st = s.structure;
    const p = st.points;
    const shift = s.lambda && player.pos >= 1 && player.pos <= s.lambda ? player.pos - 1 : null;
    const choice = shift !== null ? shifts(s)[shift]?.choice : player.pos > 0 && s.solution ? s.solution.choice : null;
    drawBackdrop(c, f, p, trianglesOf(st, choice ?? new Uint8Array(st.m)), 0.25);
    // Quads filled by layer; flipped ones hatched amber.
    const layer = s.baker?.layer ?? new Uint32Array(st.m);
    const byLayer = Array.from({ length: Math.max(1, s.layers) }, () => new Path2D());
    const flipped = new Path2D();
    for (let q = 0; q < st.m; q++) {
      const path = byLayer[layer[q]!]!;
      const corners = [st.quads[4 * q]!, st.quads[4 * q + 2]!, st.quads[4 * q + 1]!, st.quads[4 * q + 3]!];
      for (const target of choice?.[q] ? [path, flipped] : [path]) {
        corners.forEach((v, j) => (j === 0 ? target.moveTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!)) : target.lineTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!))));
        target.closePath();
      }
    }
    byLayer.forEach((path, l) => {
      c.fillStyle = layerColor(l, Math.max(1, s.layers)).replace('rgb(', 'rgba(').replace(')', ', 0.42)');
      c.fill(path);
    });
    c.strokeStyle = withAlpha(FLIPPED_COLOR, 0.95);
    c.lineWidth = 2;
    c.stroke(flipped);
    // The quad graph.
    const cx = (q: number) => f.sx(st.centroid[2 * q]!);
    const cy = (q: number) => f.sy(st.centroid[2 * q + 1]!);
    const kept = new Path2D(), cut = new Path2D();
    for (const [q, r] of st.quadEdges) {
      const lo = Math.min(layer[q]!, layer[r]!), hi = Math.max(layer[q]!, layer[r]!);
      const target = shift !== null && isCut(lo, hi, shift, s.lambda!) ? cut : kept;
      target.moveTo(cx(q), cy(q));
      target.lineTo(cx(r), cy(r));
    }
    c.strokeStyle = 'rgba(30, 42, 38, 0.55)';
    c.lineWidth = 1.3;
    c.stroke(kept);
    c.setLineDash([5, 4]);
    c.strokeStyle = CUT_COLOR;
    c.lineWidth = 2.4;
    c.stroke(cut);
    c.setLineDash([]);
    const r = st.m > 600 ? 2.2 : 3.6;
    for (let q = 0; q < st.m; q++) {
      c.beginPath();
      c.arc(cx(q), cy(q), r, 0, 2 * Math.PI);
      c.fillStyle = layerColor(layer[q]!, Math.max(1, s.layers));
      c.fill();
      c.strokeStyle = '#fff';
      c.lineWidth = 1;
      c.stroke();
    }
  }

  return {
    id: 'baker',
    label: 'Baker layers',
    root,
    activate() {
      active = true;
      follow();
      update();
      canvas.redraw();
    },
    deactivate() {
      active = false;
      player.stop();
    },
    changed() {
      follow();
      stale = true;
      token++;
      update();
    },
    hooks() {
      const s = state;
      return {
        objective: objective.value,
        epsilon: s?.epsilon ?? null,
        lambda: s?.lambda ?? null,
        layers: s?.layers ?? 0,
        position: player.pos,
        atEnd: s !== null && s.lambda !== null && player.pos === last(),
        // In the objective's units (mixed vertices: value and lower bound).
        shifts: s ? shifts(s).map((x) => ({ shift: x.shift, cut: x.dropped, relaxed: x.relaxed, value: x.value, bound: x.bound })) : [],
        library: s?.solution ? { value: s.solution.value, bound: s.solution.bound, details: s.solution.details } : null,
        failure: s?.failure ?? null,
      };
    },
  };
}
