// Teaching view: order k (paper, Section 4.3). The library's explanation of a
// solve at order k gives the useful k-OD edges, the fixed ones (useful edges no
// other crosses: in every k-OD triangulation), the regions they cut the hull
// into with the number of k-OD triangulations of each, and the optimum. Stepping
// k from 1 to 8 shows regions merge and, for local minima, pits disappear. The
// view draws what the library returned; it decides nothing itself.
import { Extremum, OBJECTIVE_IDS, type Explanation, type Measures, type ObjectiveId } from 'hodt';
import { h } from '../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../ui/objectiveHelp.ts';
import { FLIPPED_COLOR } from '../views/palette.ts';
import { withAlpha } from '../views/plan/planRenderer.ts';
import { createFittedCanvas, type FittedCanvas } from './canvas.ts';
import { COMPONENT_COLORS, createPane, legend, objectiveSelect, paperLink, stepControls, type TeachContext, type TeachView } from './common.ts';
import { StepPlayer } from './stepPlayer.ts';
import { countRegions, describeRegions, hasChoice, triangulationsMark } from '../app/regionCount.ts';

const MAX_ORDER = 8;
const FIXED_COLOR = '#1e2a26';
const MINIMUM_COLOR = '#c62828';

interface State {
  order: number;
  objective: ObjectiveId;
  explanation: Explanation | null;
  failure: string | null;
  /** Local minima of the optimum and of Delaunay (point indices), from the library's measures. */
  minima: number[];
  delaunayMinima: number[];
}

export function createOrderView(ctx: TeachContext): TeachView {
  const { root, side, main, caption } = createPane('order', 'Order k: regions and fixed edges', [
    'A triangulation is k-th order Delaunay if every triangle’s circumcircle holds at most k points. An edge is useful if some such triangulation uses it. ',
    'A useful edge that no other useful edge crosses is in every one of them (fixed, dark); the fixed edges cut the hull into regions (colours), each triangulated independently, ',
    'so the library optimises region by region (the number in a region: how many k-OD triangulations it has). As k grows, regions merge and the optimum can only improve. See ',
    paperLink('4.3'),
    '.',
  ]);
  const objective = objectiveSelect(ctx, 'order-objective', OBJECTIVE_IDS, 'Objective', () => {
    stale = true;
    update();
  });
  const counter = h('span', { class: 'teach-counter', id: 'order-counter' });
  // Positions 0..7 are the orders 1..8.
  const player = new StepPlayer(() => MAX_ORDER - 1, () => {
    stale = true;
    update();
  }, 2200);
  const controls = stepControls('order', player, counter, {
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
  const canvas = createFittedCanvas(main, (c, f) => draw(c, f), 'Regions of order k, fixed and useful edges, and the optimal triangulation');

  let active = false;
  let stale = true;
  let state: State | null = null;
  let token = 0;
  /** Value per order for the current terrain and settings (the table; cleared on any change). */
  const values = new Map<number, { value: number; optimal: boolean; bound: number | null; delaunay: number }>();

  function update(): void {
    if (!active || !stale) return;
    stale = false;
    const my = ++token;
    const order = player.pos + 1;
    const id = objective.value as ObjectiveId;
    const { method, epsilon, maxEdge } = ctx.settings();
    state = { order, objective: id, explanation: null, failure: null, minima: [], delaunayMinima: [] };
    canvas.fit(ctx.points());
    render();
    void ctx.solver.solve({ points: ctx.points(), objective: id, method, epsilon, order, maxEdge, explain: true }).then((o) => {
      if (my !== token || !state) return;
      if (o.status === 'solved' && o.explanation) {
        const e = o.explanation;
        state.explanation = e;
        const terrain = ctx.terrain();
        state.minima = minimaOf(terrain.measuresOfTriangles(e.solution.triangles));
        state.delaunayMinima = minimaOf(terrain.measures());
        values.set(order, { value: e.solution.value, optimal: e.solution.optimal, bound: e.solution.bound, delaunay: e.solution.delaunayValue });
      } else {
        state.failure = o.status === 'failed' ? o.message : 'cancelled';
      }
      render();
    });
  }

  function render(): void {
    canvas.redraw();
    const s = state;
    if (!s) return;
    const fmt = (v: number) => formatValue(s.objective, v);
    counter.textContent = `k = ${s.order}`;
    const e = s.explanation;
    const r = e?.regions ?? null;
    const count = r ? countRegions(r) : null;
    caption.textContent = count ? `Order ${s.order}: ${describeRegions(count)}` : `Order ${s.order}`;
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
    const rows = [...values.entries()].sort((a, b) => a[0] - b[0]);
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

  function draw(c: CanvasRenderingContext2D, f: FittedCanvas): void {
    const s = state;
    const r = s?.explanation?.regions;
    if (!s || !r) return;
    const p = ctx.points();
    const X = (v: number) => f.sx(p[3 * v]!), Y = (v: number) => f.sy(p[3 * v + 1]!);
    // Regions with a choice, one colour each; the rest pale.
    const paths = new Map<number, Path2D>();
    const single = new Path2D();
    for (let t = 0; t < r.regionOfTriangle.length; t++) {
      const g = r.regionOfTriangle[t]!;
      const path = hasChoice(r, g) ? (paths.get(g) ?? paths.set(g, new Path2D()).get(g)!) : single;
      const [a, b, d] = [r.triangles[3 * t]!, r.triangles[3 * t + 1]!, r.triangles[3 * t + 2]!];
      path.moveTo(X(a), Y(a));
      path.lineTo(X(b), Y(b));
      path.lineTo(X(d), Y(d));
      path.closePath();
    }
    c.fillStyle = '#eef1ef';
    c.fill(single);
    for (const [g, path] of paths) {
      c.fillStyle = withAlpha(COMPONENT_COLORS[g % COMPONENT_COLORS.length]!, 0.28);
      c.fill(path);
    }
    // Useful edges (dashed), then the optimum's edges, then fixed edges on top.
    const useful = new Path2D();
    for (let i = 0; i < r.useful.length; i += 2) {
      useful.moveTo(X(r.useful[i]!), Y(r.useful[i]!));
      useful.lineTo(X(r.useful[i + 1]!), Y(r.useful[i + 1]!));
    }
    c.setLineDash([3, 3]);
    c.strokeStyle = 'rgba(110, 122, 118, 0.55)';
    c.lineWidth = 0.8;
    c.stroke(useful);
    c.setLineDash([]);
    const delaunay = new Set<number>();
    const key = (u: number, v: number) => (u < v ? u * 0x200000 + v : v * 0x200000 + u);
    for (let t = 0; t < r.triangles.length; t += 3) for (let j = 0; j < 3; j++) delaunay.add(key(r.triangles[t + j]!, r.triangles[t + ((j + 1) % 3)]!));
    const tri = s.explanation!.solution.triangles;
    const chosen = new Path2D(), changed = new Path2D();
    for (let t = 0; t < tri.length; t += 3) {
      for (let j = 0; j < 3; j++) {
        const u = tri[t + j]!, v = tri[t + ((j + 1) % 3)]!;
        const path = delaunay.has(key(u, v)) ? chosen : changed;
        path.moveTo(X(u), Y(u));
        path.lineTo(X(v), Y(v));
      }
    }
    c.strokeStyle = 'rgba(40, 50, 46, 0.35)';
    c.lineWidth = 0.8;
    c.stroke(chosen);
    c.strokeStyle = withAlpha(FLIPPED_COLOR, 0.95);
    c.lineWidth = 2.2;
    c.stroke(changed);
    const fixed = new Path2D();
    for (let i = 0; i < r.fixed.length; i += 2) {
      fixed.moveTo(X(r.fixed[i]!), Y(r.fixed[i]!));
      fixed.lineTo(X(r.fixed[i + 1]!), Y(r.fixed[i + 1]!));
    }
    c.strokeStyle = FIXED_COLOR;
    c.lineWidth = 1.4;
    c.stroke(fixed);
    // Triangulation counts, where there is room.
    if (paths.size <= 200) {
      const sum = new Map<number, [number, number, number]>();
      for (let t = 0; t < r.regionOfTriangle.length; t++) {
        const g = r.regionOfTriangle[t]!;
        if (!hasChoice(r, g)) continue;
        const acc = sum.get(g) ?? sum.set(g, [0, 0, 0]).get(g)!;
        for (let j = 0; j < 3; j++) (acc[0] += X(r.triangles[3 * t + j]!) / 3), (acc[1] += Y(r.triangles[3 * t + j]!) / 3);
        acc[2]++;
      }
      c.font = '600 11px system-ui, sans-serif';
      c.textAlign = 'center';
      c.textBaseline = 'middle';
      for (const [g, [x, y, n]] of sum) {
        const label = triangulationsMark(r.triangulations[g]!, r.complete[g] === 1);
        c.lineWidth = 3;
        c.strokeStyle = 'rgba(255, 255, 255, 0.9)';
        c.strokeText(label, x / n, y / n);
        c.fillStyle = '#14201c';
        c.fillText(label, x / n, y / n);
      }
    }
    // Local minima: filled for the optimum, hollow for Delaunay's that are gone.
    const now = new Set(s.minima);
    for (const v of s.delaunayMinima) {
      if (now.has(v)) continue;
      c.beginPath();
      c.arc(X(v), Y(v), 4.5, 0, 2 * Math.PI);
      c.strokeStyle = MINIMUM_COLOR;
      c.lineWidth = 1.5;
      c.stroke();
    }
    for (const v of s.minima) {
      c.beginPath();
      c.arc(X(v), Y(v), 4.5, 0, 2 * Math.PI);
      c.fillStyle = MINIMUM_COLOR;
      c.fill();
    }
  }

  return {
    id: 'order',
    label: 'Order k',
    root,
    activate() {
      active = true;
      objective.value = ctx.settings().objective;
      update();
      canvas.redraw();
    },
    deactivate() {
      active = false;
      player.stop();
    },
    changed() {
      objective.value = ctx.settings().objective;
      values.clear();
      stale = true;
      update();
    },
    hooks() {
      const s = state;
      const r = s?.explanation?.regions ?? null;
      return {
        order: s?.order ?? null,
        objective: s?.objective ?? null,
        value: s?.explanation?.solution.value ?? null,
        optimal: s?.explanation?.solution.optimal ?? null,
        regions: r ? r.triangulations.length : null,
        withChoice: r ? countRegions(r).withChoice : null,
        caption: caption.textContent,
        useful: r ? r.useful.length / 2 : null,
        fixed: r ? r.fixed.length / 2 : null,
        minima: s?.minima.length ?? null,
        failure: s?.failure ?? null,
      };
    },
  };
}

/** The local minima (point indices) the library's measures mark. */
function minimaOf(m: Measures): number[] {
  const out: number[] = [];
  m.extremum.forEach((x, v) => x === Extremum.Minimum && out.push(v));
  return out;
}

