// Teaching view 1: the bottleneck search of Section 2.1 step by step. The library
// solves with { trace: true }; for each threshold it tested, this view rebuilds
// the eliminations and the 2-SAT instance in TypeScript and draws them.
import type { Solution } from 'hodt';
import { h } from '../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../ui/objectiveHelp.ts';
import { CRITICAL_COLOR, FLIPPED_COLOR, QUAD_COLOR } from '../views/palette.ts';
import { withAlpha } from '../views/plan/planRenderer.ts';
import { createFittedCanvas, drawBackdrop, trianglePath, type FittedCanvas } from './canvas.ts';
import { jitteredGridPoints } from '../terrains/jitteredGrid.ts';
import { button, COMPONENT_COLORS, createPane, paperLink, type TeachContext, type TeachView } from './common.ts';
import { analyseStep, buildPairModel, isPairObjective, PAIR_OBJECTIVES, type PairModel, type PairObjective, type Source, type StepAnalysis } from './pairModel.ts';
import { readStructure, trianglesOf, type QuadStructure } from './structure.ts';
import { StepPlayer } from './stepPlayer.ts';

const OVER_COLOR = '#f28e2b';
const BLOCK_COLOR = '#c62828';
const SVG = 'http://www.w3.org/2000/svg';

interface State {
  structure: QuadStructure;
  model: PairModel;
  solution: Solution;
  steps: (StepAnalysis | null)[];
  /** Index in model.candidates of each tested threshold. */
  rank: number[];
  /** Steps whose analysis here disagrees with the library's trace. */
  mismatches: number[];
}

export function createSatView(ctx: TeachContext): TeachView {
  const { root, side, main, caption } = createPane('sat', '2-SAT search for min-max objectives', [
    'A min-max objective is the worst value over pairs of adjacent triangles. Only a few values can be the optimum: the candidates on the line below. ',
    'The solver asks, by binary search: "is there a first order triangulation with every pair at most t?" ',
    'Pairs of fixed triangles over t answer no at once; a quad with one diagonal over t is forced to the other; every remaining pair over t between two quads becomes 2-SAT clauses on their diagonals, ',
    'solved through the strongly connected components of the implication graph. See ',
    paperLink('2.1'),
    '.',
  ]);
  const objective = h('select', { id: 'sat-objective', 'aria-label': 'Pair objective' });
  objective.replaceChildren(...PAIR_OBJECTIVES.map((id) => h('option', { value: id }, OBJECTIVE_HELP[id].name)));
  objective.addEventListener('change', () => {
    stale = true;
    update();
  });
  // A jittered grid: its many adjacent quads give 2-SAT instances with clauses
  // between quads and answers "no" found by the components, not only at once.
  const small = button('sat-small', 'Example', 'Load a 60-point jittered grid (49 quads) whose search has clauses between quads', () =>
    ctx.load(jitteredGridPoints(60, 15), 'load the 2-SAT example', objective.value as PairObjective),
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
  const play = button('sat-play', '▶ Play', 'Step through the search', () => player.toggle());
  player.attach(play);
  const controls = h(
    'div',
    { class: 'teach-controls' },
    button('sat-first', 'Start', 'Back to the start', () => player.go(0)),
    button('sat-prev', '◀ Prev', 'Previous step', () => player.go(player.pos - 1)),
    play,
    button('sat-next', 'Next ▶', 'Next step', () => player.go(player.pos + 1)),
    counter,
  );
  const legend = h(
    'ul',
    { class: 'teach-legend' },
    item('fill', QUAD_COLOR, 'forced to keep its Delaunay diagonal'),
    item('fill', FLIPPED_COLOR, 'forced (or chosen) to flip'),
    item('fill', BLOCK_COLOR, 'both diagonals over t: no'),
    item('line', OVER_COLOR, 'pair over t (depends on quads)'),
    item('line', BLOCK_COLOR, 'fixed pair over t: no'),
    item('line', '#4d5753', 'clause between two quads (component colour)'),
  );
  side.append(h('div', { class: 'row' }, objective, small), line, controls, status, list, legend);
  const canvas = createFittedCanvas(main, (c, f) => draw(c, f), '2-SAT step: the terrain, forced quads, pairs over the threshold and the implication graph');

  let active = false;
  let stale = true;
  let state: State | null = null;
  let error: string | null = null;

  function update(): void {
    if (!active || !stale) return;
    stale = false;
    player.stop();
    const id = objective.value as PairObjective;
    try {
      const terrain = ctx.terrain();
      const structure = readStructure(terrain);
      const model = buildPairModel(structure, id);
      const solution = terrain.solve(id, { trace: true });
      const rank = solution.trace.map((t) => nearest(model.candidates, t.threshold));
      state = { structure, model, solution, steps: solution.trace.map(() => null), rank, mismatches: [] };
      error = null;
      canvas.fit(structure.points);
    } catch (e) {
      state = null;
      error = e instanceof Error ? e.message : String(e);
    }
    player.pos = 0;
    render();
  }

  function stepAt(i: number): StepAnalysis {
    const s = state!;
    let a = s.steps[i];
    if (!a) {
      const t = s.solution.trace[i]!;
      a = analyseStep(s.model, s.structure.m, t.threshold);
      s.steps[i] = a;
      const same = a.satisfiable === t.satisfiable && a.immediateNo === t.immediateNo && (t.immediateNo || (a.clauses === t.clauses && a.forced.length === t.forced));
      if (!same && !s.mismatches.includes(i)) s.mismatches.push(i);
    }
    return a;
  }

  const last = () => (state ? state.solution.trace.length + 1 : 0);

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
    const id = s.model.objective;
    const fmt = (v: number) => formatValue(id, v);
    const n = s.solution.trace.length;
    counter.textContent = player.pos === 0 ? 'start' : player.pos > n ? 'done' : `step ${player.pos} of ${n}`;
    caption.textContent =
      player.pos === 0
        ? 'Delaunay triangulation · flippable quads in pale teal'
        : player.pos > n
          ? `Optimum: ${fmt(s.solution.value)} · flipped quads amber, worst pair pink`
          : `Step ${player.pos}: t = ${fmt(s.solution.trace[player.pos - 1]!.threshold)} · ${s.solution.trace[player.pos - 1]!.satisfiable ? 'yes: the 2-SAT solution shown' : 'no'}`;
    // The step list.
    list.replaceChildren(
      ...s.solution.trace.map((t, i) => {
        const li = h(
          'li',
          { class: `${t.satisfiable ? 'yes' : 'no'}${i + 1 === player.pos ? ' current' : ''}`, 'data-threshold': String(t.threshold) },
          h('b', {}, `t = ${fmt(t.threshold)}`),
          ` ${t.satisfiable ? '✓ yes' : '✗ no'}`,
          h('span', { class: 'muted' }, t.immediateNo ? ' · immediate no' : ` · ${t.clauses} clause${t.clauses === 1 ? '' : 's'} · ${t.forced} forced`),
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
        `${s.model.candidates.length} candidate values lie between the lower bound (${fmt(s.model.candidates[0]!)}) and the Delaunay value (${fmt(s.solution.delaunayValue)}). `,
        `Binary search tests ${n} of them. Press Next.`,
      );
    } else if (player.pos <= n) {
      const t = s.solution.trace[player.pos - 1]!;
      const a = stepAt(player.pos - 1);
      const parts: (string | Node)[] = [h('b', {}, `Is there a triangulation with ${measure} ≤ ${fmt(t.threshold)}? `)];
      if (a.fixedOver.length) parts.push(`${a.fixedOver.length} pair${a.fixedOver.length === 1 ? '' : 's'} of fixed triangles exceed it: no, immediately. `);
      else if (a.blocked.length) parts.push(`${a.blocked.length} quad${a.blocked.length === 1 ? ' has' : 's have'} both diagonals over it: no, immediately. `);
      else {
        parts.push(
          `${a.forced.length} quad${a.forced.length === 1 ? ' is' : 's are'} forced, ${a.constraints.length} pair${a.constraints.length === 1 ? '' : 's'} of quads constrain each other (${a.clauses} clauses in all). `,
          a.satisfiable
            ? 'The implication graph has no quad whose two diagonals are in one strongly connected component: yes, satisfiable (the diagonals shown). '
            : `${a.sat!.conflicts.length} quad${a.sat!.conflicts.length === 1 ? ' has' : 's have'} both diagonals in one strongly connected component (✕): no. `,
        );
      }
      parts.push(t.satisfiable ? 'The optimum is at most t: search below.' : 'The optimum is above t: search above.');
      if (s.mismatches.includes(player.pos - 1)) parts.push(h('span', { class: 'warn' }, ' (this page’s doubles disagree with the library here; the library is right)'));
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
    const N = s.model.candidates.length;
    const x = (i: number) => 20 + (290 * i) / Math.max(1, N - 1);
    const el = (tag: string, attrs: Record<string, string | number>, text?: string) => {
      const e = document.createElementNS(SVG, tag);
      for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
      if (text !== undefined) e.textContent = text;
      return e;
    };
    const steps = s.solution.trace.length;
    const rowY = (i: number) => 50 + 15 * i;
    const height = rowY(steps) + 10;
    line.setAttribute('viewBox', `0 0 320 ${height}`);
    const nodes: SVGElement[] = [];
    const fmt = (v: number) => formatValue(s.model.objective, v);
    nodes.push(el('text', { x: 16, y: 10, 'font-size': 10, fill: '#5d6b66' }, `${fmt(s.model.candidates[0]!)} (lower bound)`));
    nodes.push(el('text', { x: 314, y: 10, 'font-size': 10, 'text-anchor': 'end', fill: '#5d6b66' }, `${fmt(s.model.candidates[N - 1]!)} (Delaunay)`));
    nodes.push(el('line', { x1: 16, x2: 314, y1: 22, y2: 22, stroke: '#8a9691', 'stroke-width': 1 }));
    const stride = Math.max(1, Math.ceil(N / 120));
    for (let i = 0; i < N; i += stride) nodes.push(el('line', { x1: x(i), x2: x(i), y1: 18, y2: 26, stroke: '#aab3af', 'stroke-width': 0.8 }));
    nodes.push(el('text', { x: 165, y: 38, 'font-size': 9.5, 'text-anchor': 'middle', fill: '#8a9691' }, `${N} candidate values, in increasing order; a row per test`));
    let lo = 0, hi = N - 1;
    const upto = Math.min(player.pos, steps);
    s.solution.trace.forEach((t, i) => {
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
      const cx = x(nearest(s.model.candidates, s.solution.value));
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
    const n = s.solution.trace.length;
    const a = player.pos >= 1 && player.pos <= n ? stepAt(player.pos - 1) : null;
    const choice = player.pos > n ? s.solution.choice : a?.sat?.assignment ?? new Uint8Array(st.m);
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
      for (const [q, x] of a.forced) quadPath(x ? flip : keep, q);
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
    // Pairs over the threshold.
    const drawSources = (sources: Source[], color: string, width: number) => {
      c.beginPath();
      for (const src of sources) {
        if (src.kind === 'edge') {
          c.moveTo(f.sx(p[3 * src.u]!), f.sy(p[3 * src.u + 1]!));
          c.lineTo(f.sx(p[3 * src.v]!), f.sy(p[3 * src.v + 1]!));
        } else if (src.kind === 'vertex') {
          const x = f.sx(p[3 * src.v]!), y = f.sy(p[3 * src.v + 1]!);
          c.moveTo(x + 7, y);
          c.arc(x, y, 7, 0, 2 * Math.PI);
        }
      }
      c.strokeStyle = color;
      c.lineWidth = width;
      c.lineCap = 'round';
      c.stroke();
    };
    const overSources: Source[] = [];
    for (const k of a.constraints) overSources.push(...k.term.sources.filter((x) => x.kind !== 'quad'));
    for (const [q] of a.forced) {
      const t = s.model.terms.find((x) => x.r < 0 && x.q === q);
      if (t) overSources.push(...t.sources.filter((x) => x.kind !== 'quad'));
    }
    drawSources(overSources, withAlpha(OVER_COLOR, 0.9), 3);
    drawSources(a.fixedOver, BLOCK_COLOR, 4);
    // The implication graph: a segment per pair of constrained quads, coloured by
    // strongly connected component.
    const colorOf = (q: number): string | null => {
      if (!a.sat) return null;
      for (const lit of [2 * q + 1, 2 * q]) {
        const comp = a.sat.component[lit]!;
        if (a.sat.componentSize[comp]! > 1) return COMPONENT_COLORS[comp % COMPONENT_COLORS.length]!;
      }
      return null;
    };
    const cx = (q: number) => f.sx(st.centroid[2 * q]!);
    const cy = (q: number) => f.sy(st.centroid[2 * q + 1]!);
    c.lineWidth = 2.2;
    for (const k of a.constraints) {
      const { q, r } = k.term;
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
    for (const k of a.constraints) involved.add(k.term.q).add(k.term.r);
    for (const q of involved) {
      c.beginPath();
      c.arc(cx(q), cy(q), 4.2, 0, 2 * Math.PI);
      c.fillStyle = colorOf(q) ?? '#4d5753';
      c.fill();
      c.strokeStyle = '#fff';
      c.lineWidth = 1.2;
      c.stroke();
    }
    for (const q of a.sat?.conflicts ?? []) {
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
      const page = ctx.settings().objective;
      if (isPairObjective(page) && page !== objective.value && !state) objective.value = page;
      update();
      canvas.redraw();
    },
    deactivate() {
      active = false;
      player.stop();
    },
    changed() {
      stale = true;
      update();
    },
    hooks() {
      const s = state;
      return {
        objective: objective.value,
        steps: s ? s.solution.trace.length : 0,
        position: player.pos,
        atEnd: s !== null && player.pos === last(),
        value: s?.solution.value ?? null,
        trace: s?.solution.trace ?? [],
        mismatches: s?.mismatches ?? [],
        error,
      };
    },
  };
}

function quadSlots(st: QuadStructure): number[] {
  return Array.from(st.quadSlots).filter((k) => k >= 0);
}

function nearest(sorted: number[], v: number): number {
  let best = 0;
  for (let i = 1; i < sorted.length; i++) if (Math.abs(sorted[i]! - v) < Math.abs(sorted[best]! - v)) best = i;
  return best;
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

function item(kind: 'fill' | 'line', color: string, label: string): HTMLLIElement {
  return h('li', {}, h('i', { class: kind === 'fill' ? 'fill' : 'line thick', style: `--c: ${color}` }), label);
}
