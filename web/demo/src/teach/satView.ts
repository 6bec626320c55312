// Teaching view 1: the bottleneck search of Section 2.1 step by step, as the
// library ran it: terrain.explain gives every threshold it tested with the quads
// it forced, its 2-SAT clauses, their strongly connected components and the
// assignment. This view only draws them.
import type { ObjectiveId, SearchExplanation, Solution, ThresholdTest } from 'hodt';
import { h } from '../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../ui/objectiveHelp.ts';
import { CRITICAL_COLOR, FLIPPED_COLOR, QUAD_COLOR } from '../views/palette.ts';
import { withAlpha } from '../views/plan/planRenderer.ts';
import { createFittedCanvas, drawBackdrop, trianglePath, type FittedCanvas } from './canvas.ts';
import { jitteredGridPoints } from '../terrains/jitteredGrid.ts';
import { button, COMPONENT_COLORS, createPane, legend, objectiveSelect, paperLink, stepControls, type TeachContext, type TeachView } from './common.ts';
import { readStructure, trianglesOf, type QuadStructure } from './structure.ts';
import { StepPlayer } from './stepPlayer.ts';

const PAIR_OBJECTIVES = [
  'minmax-edge-area-ratio',
  'minmax-edge-normal-angle',
  'minmax-edge-enclosing-circle',
  'minmax-vertex-area-ratio',
  'minmax-vertex-normal-angle',
] as const satisfies readonly ObjectiveId[];
type PairObjective = (typeof PAIR_OBJECTIVES)[number];
const isPairObjective = (id: string): id is PairObjective => (PAIR_OBJECTIVES as readonly string[]).includes(id);

const BLOCK_COLOR = '#c62828';
const SVG = 'http://www.w3.org/2000/svg';

interface State {
  structure: QuadStructure;
  objective: PairObjective;
  search: SearchExplanation;
  solution: Solution;
  /** Index in search.candidates of each tested threshold. */
  rank: number[];
}

export function createSatView(ctx: TeachContext): TeachView {
  const { root, side, main, caption } = createPane('sat', '2-SAT search for min-max objectives', [
    'A min-max objective is the worst value over pairs of adjacent triangles. Only a few values can be the optimum: the candidates on the line below. ',
    'The solver asks, by binary search (the lower bound first: it is often the optimum): "is there a first order triangulation with every pair at most t?" ',
    'Pairs of fixed triangles over t answer no at once; a quad with one diagonal over t is forced to the other; every remaining pair over t between two quads becomes 2-SAT clauses on their diagonals, ',
    'solved through the strongly connected components of the implication graph. See ',
    paperLink('2.1'),
    '.',
  ]);
  const objective = objectiveSelect(ctx, 'sat-objective', PAIR_OBJECTIVES, 'Pair objective', () => {
    stale = true;
    update();
  });
  // A jittered grid: its many adjacent quads give 2-SAT instances with clauses
  // between quads and answers "no" found by the components, not only at once.
  const example = jitteredGridPoints(64, 15);
  const gridSide = Math.round(Math.sqrt(example.length / 3));
  const small = button('sat-small', 'Example', `Load a ${example.length / 3}-point jittered grid (${gridSide} x ${gridSide}, seed 15) whose search has clauses between quads`, () =>
    ctx.load(example, 'load the 2-SAT example', objective.value as PairObjective, { kind: 'grid', count: example.length / 3, seed: 15 }),
  );
  const line = document.createElementNS(SVG, 'svg');
  line.setAttribute('class', 'sat-line');
  line.setAttribute('viewBox', '0 0 320 40');
  line.setAttribute('role', 'img');
  line.setAttribute('aria-label', 'Candidate values and tested thresholds');
  const status = h('p', { class: 'teach-status', id: 'sat-status', 'aria-live': 'polite' });
  const list = h('ol', { class: 'sat-steps', id: 'sat-steps' });
  const counter = h('span', { class: 'teach-counter', id: 'sat-counter' });
  const player = new StepPlayer(() => last(), () => render(), 1300);
  const controls = stepControls('sat', player, counter, {
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
  const canvas = createFittedCanvas(main, (c, f) => draw(c, f), '2-SAT step: the terrain, forced quads, pairs over the threshold and the implication graph');

  let active = false;
  let stale = true;
  let state: State | null = null;
  let error: string | null = null;

  /** The sidebar's objective, when it is one this view shows. */
  function follow(): void {
    const page = ctx.settings().objective;
    if (isPairObjective(page)) objective.value = page;
  }

  function update(): void {
    if (!active || !stale) return;
    stale = false;
    player.stop();
    const id = objective.value as PairObjective;
    try {
      const terrain = ctx.terrain();
      const structure = readStructure(terrain);
      const { search, solution } = terrain.explain(id);
      if (!search) throw new Error(`the library ran no threshold search for ${id}`);
      const rank = search.tests.map((t) => search.candidates.indexOf(t.threshold));
      state = { structure, objective: id, search, solution, rank };
      error = null;
      canvas.fit(structure.points);
    } catch (e) {
      state = null;
      error = e instanceof Error ? e.message : String(e);
    }
    player.pos = 0;
    render();
  }

  const stepAt = (i: number): ThresholdTest => state!.search.tests[i]!;

  const last = () => (state ? state.search.tests.length + 1 : 0);

  function render(): void {
    canvas.redraw();
    if (!state) {
      status.textContent = error ? `Cannot show the search: ${error}` : '';
      list.replaceChildren();
      line.replaceChildren();
      counter.textContent = '';
      return;
    }
    const s = state;
    const id = s.objective;
    const fmt = (v: number) => formatValue(id, v);
    const n = s.search.tests.length;
    counter.textContent = player.pos === 0 ? 'start' : player.pos > n ? 'done' : `step ${player.pos} of ${n}`;
    caption.textContent =
      player.pos === 0
        ? 'Delaunay triangulation · flippable quads in pale teal'
        : player.pos > n
          ? `Optimum: ${fmt(s.solution.value)} · flipped quads amber, worst pair pink`
          : `Step ${player.pos}: t = ${fmt(stepAt(player.pos - 1).threshold)} · ${stepAt(player.pos - 1).satisfiable ? 'yes: the 2-SAT solution shown' : 'no'}`;
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
    drawLine(s);
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
      const a = stepAt(player.pos - 1);
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
    publish();
  }

  function final(sol: Solution): HTMLElement {
    return h('b', { id: 'sat-final', 'data-value': String(sol.value) }, formatValue(sol.objective, sol.value));
  }

  /** The number line: the candidates in increasing order (evenly spaced), then a
   * row per step: the interval still open before it (blue) and the threshold it
   * tested (green yes, red no); the optimum marked at the end. */
  function drawLine(s: State): void {
    const N = s.search.candidates.length;
    const x = (i: number) => 20 + (290 * i) / Math.max(1, N - 1);
    const el = (tag: string, attrs: Record<string, string | number>, text?: string) => {
      const e = document.createElementNS(SVG, tag);
      for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
      if (text !== undefined) e.textContent = text;
      return e;
    };
    const steps = s.search.tests.length;
    const rowY = (i: number) => 50 + 15 * i;
    const height = rowY(steps) + 10;
    line.setAttribute('viewBox', `0 0 320 ${height}`);
    const nodes: SVGElement[] = [];
    const fmt = (v: number) => formatValue(s.objective, v);
    nodes.push(el('text', { x: 16, y: 10, 'font-size': 10, fill: '#5d6b66' }, `${fmt(s.search.candidates[0]!)} (lower bound)`));
    nodes.push(el('text', { x: 314, y: 10, 'font-size': 10, 'text-anchor': 'end', fill: '#5d6b66' }, `${fmt(s.search.candidates[N - 1]!)} (Delaunay)`));
    nodes.push(el('line', { x1: 16, x2: 314, y1: 22, y2: 22, stroke: '#8a9691', 'stroke-width': 1 }));
    const stride = Math.max(1, Math.ceil(N / 120));
    for (let i = 0; i < N; i += stride) nodes.push(el('line', { x1: x(i), x2: x(i), y1: 18, y2: 26, stroke: '#aab3af', 'stroke-width': 0.8 }));
    nodes.push(el('text', { x: 165, y: 38, 'font-size': 9.5, 'text-anchor': 'middle', fill: '#8a9691' }, `${N} candidate values, in increasing order; a row per test`));
    let lo = 0, hi = N - 1;
    const upto = Math.min(player.pos, steps);
    s.search.tests.forEach((t, i) => {
      const y = rowY(i);
      const current = i + 1 === player.pos;
      const shown = i < upto;
      nodes.push(el('text', { x: 2, y: y + 3.5, 'font-size': 10, fill: shown ? '#1e2a26' : '#c3cac7', 'font-weight': current ? 700 : 400 }, String(i + 1)));
      nodes.push(el('rect', { x: x(lo) - 3, y: y - 4, width: Math.max(6, x(hi) - x(lo) + 6), height: 8, rx: 4, fill: shown ? 'rgba(31, 119, 180, 0.16)' : 'rgba(31, 119, 180, 0.05)' }));
      const r = s.rank[i]!;
      if (shown) {
        const color = t.satisfiable ? '#17804a' : BLOCK_COLOR;
        nodes.push(el('circle', { cx: x(r), cy: y, r: current ? 5 : 3.8, fill: color, stroke: current ? '#111' : '#fff', 'stroke-width': current ? 1.6 : 1 }));
      }
      if (t.satisfiable) hi = r;
      else lo = r + 1;
    });
    if (player.pos > steps) {
      const y = rowY(steps);
      const cx = x(Math.max(0, s.search.candidates.indexOf(s.solution.value)));
      nodes.push(el('path', { d: `M${cx} ${y - 6} l5 9 h-10 z`, fill: '#111' }));
      nodes.push(el('text', { x: cx + (cx > 200 ? -8 : 8), y: y + 3, 'font-size': 10, 'font-weight': 700, 'text-anchor': cx > 200 ? 'end' : 'start', fill: '#111' }, `optimum ${fmt(s.solution.value)}`));
    }
    line.replaceChildren(...nodes);
  }

  function draw(c: CanvasRenderingContext2D, f: FittedCanvas): void {
    if (!state) return;
    const s = state;
    const st = s.structure;
    const p = st.points;
    const n = s.search.tests.length;
    const a = player.pos >= 1 && player.pos <= n ? stepAt(player.pos - 1) : null;
    const choice = player.pos > n ? s.solution.choice : a && a.assignment.length ? a.assignment : new Uint8Array(st.m);
    const triangles = trianglesOf(st, choice);
    drawBackdrop(c, f, p, triangles);
    // Quads: faint; flipped amber; forced strong; blocked red.
    const faint = new Path2D(), flipped = new Path2D(), keep = new Path2D(), flip = new Path2D(), blocked = new Path2D();
    const quadPath = (path: Path2D, q: number) => {
      const [a0, b0, c0, d0] = [st.quads[4 * q]!, st.quads[4 * q + 2]!, st.quads[4 * q + 1]!, st.quads[4 * q + 3]!];
      [a0, b0, c0, d0].forEach((v, j) => (j === 0 ? path.moveTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!)) : path.lineTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!))));
      path.closePath();
    };
    for (let q = 0; q < st.m; q++) quadPath(choice[q] ? flipped : faint, q);
    if (a) {
      for (let k = 0; k < a.forced.length; k += 2) quadPath(a.forced[k + 1] ? flip : keep, a.forced[k]!);
      for (const q of a.blocked) quadPath(blocked, q);
    }
    c.fillStyle = withAlpha(QUAD_COLOR, 0.16);
    c.fill(faint);
    c.fillStyle = withAlpha(FLIPPED_COLOR, 0.45);
    c.fill(flipped);
    c.fillStyle = withAlpha(QUAD_COLOR, 0.6);
    c.fill(keep);
    c.fillStyle = withAlpha(FLIPPED_COLOR, 0.85);
    c.fill(flip);
    c.fillStyle = withAlpha(BLOCK_COLOR, 0.6);
    c.fill(blocked);
    c.lineWidth = 1.6;
    c.strokeStyle = 'rgba(20, 30, 26, 0.7)';
    c.stroke(keep);
    c.stroke(flip);
    // The chosen diagonals, drawn again on top.
    c.strokeStyle = 'rgba(40, 50, 46, 0.55)';
    c.lineWidth = 1;
    c.stroke(trianglePath(f, p, triangles, quadSlots(st)));
    if (player.pos > n && s.solution.critical) {
      const crit = new Path2D();
      for (const t of [s.solution.critical.first, s.solution.critical.second]) {
        t.forEach((v, j) => (j === 0 ? crit.moveTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!)) : crit.lineTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!))));
        crit.closePath();
      }
      c.fillStyle = withAlpha(CRITICAL_COLOR, 0.35);
      c.fill(crit);
      c.strokeStyle = CRITICAL_COLOR;
      c.lineWidth = 2;
      c.stroke(crit);
    }
    if (!a) return;
    // The implication graph: a segment per pair of constrained quads, coloured by
    // strongly connected component.
    const size = new Map<number, number>();
    for (const comp of a.component) if (comp >= 0) size.set(comp, (size.get(comp) ?? 0) + 1);
    const colorOf = (q: number): string | null => {
      for (const lit of [2 * q + 1, 2 * q]) {
        const comp = a.component[lit] ?? -1;
        if (comp >= 0 && size.get(comp)! > 1) return COMPONENT_COLORS[comp % COMPONENT_COLORS.length]!;
      }
      return null;
    };
    const pairs = quadPairs(a);
    const cx = (q: number) => f.sx(st.centroid[2 * q]!);
    const cy = (q: number) => f.sy(st.centroid[2 * q + 1]!);
    c.lineWidth = 2.2;
    for (const [q, r] of pairs) {
      const cq = colorOf(q), cr = colorOf(r);
      c.strokeStyle = cq && cq === cr ? cq : '#4d5753';
      c.beginPath();
      c.moveTo(cx(q), cy(q));
      c.lineTo(cx(r), cy(r));
      c.stroke();
      arrowHead(c, cx(q), cy(q), cx(r), cy(r));
      arrowHead(c, cx(r), cy(r), cx(q), cy(q));
    }
    const involved = new Set<number>();
    for (const [q, r] of pairs) involved.add(q).add(r);
    for (const q of involved) {
      c.beginPath();
      c.arc(cx(q), cy(q), 4.2, 0, 2 * Math.PI);
      c.fillStyle = colorOf(q) ?? '#4d5753';
      c.fill();
      c.strokeStyle = '#fff';
      c.lineWidth = 1.2;
      c.stroke();
    }
    for (const q of a.conflicts) {
      const x = cx(q), y = cy(q);
      c.strokeStyle = BLOCK_COLOR;
      c.lineWidth = 3;
      c.beginPath();
      c.moveTo(x - 7, y - 7);
      c.lineTo(x + 7, y + 7);
      c.moveTo(x + 7, y - 7);
      c.lineTo(x - 7, y + 7);
      c.stroke();
    }
  }

  function publish(): void {
    // hooks() is read on demand; nothing to push.
  }

  return {
    id: 'sat',
    label: '2-SAT search',
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
      update();
    },
    hooks() {
      const s = state;
      return {
        objective: objective.value,
        steps: s ? s.search.tests.length : 0,
        position: player.pos,
        atEnd: s !== null && player.pos === last(),
        value: s?.solution.value ?? null,
        tests: s?.search.tests.map((t) => ({ threshold: t.threshold, satisfiable: t.satisfiable, clauses: t.clauses.length / 2, conflicts: t.conflicts.length })) ?? [],
        error,
      };
    },
  };
}

function quadSlots(st: QuadStructure): number[] {
  return Array.from(st.quadSlots).filter((k) => k >= 0);
}

/** The pairs of distinct quads the test's clauses join, each once. */
function quadPairs(t: ThresholdTest): [number, number][] {
  const seen = new Set<number>();
  const out: [number, number][] = [];
  for (let k = 0; k < t.clauses.length; k += 2) {
    const q = Math.min(t.clauses[k]! >> 1, t.clauses[k + 1]! >> 1), r = Math.max(t.clauses[k]! >> 1, t.clauses[k + 1]! >> 1);
    if (q === r || seen.has(q * 0x100000 + r)) continue;
    seen.add(q * 0x100000 + r);
    out.push([q, r]);
  }
  return out;
}

function arrowHead(c: CanvasRenderingContext2D, x0: number, y0: number, x1: number, y1: number): void {
  const len = Math.hypot(x1 - x0, y1 - y0);
  if (len < 18) return;
  const ux = (x1 - x0) / len, uy = (y1 - y0) / len;
  const tx = x1 - ux * 7, ty = y1 - uy * 7;
  c.beginPath();
  c.moveTo(tx, ty);
  c.lineTo(tx - ux * 6 - uy * 3.5, ty - uy * 6 + ux * 3.5);
  c.lineTo(tx - ux * 6 + uy * 3.5, ty - uy * 6 - ux * 3.5);
  c.closePath();
  c.fillStyle = c.strokeStyle;
  c.fill();
}

