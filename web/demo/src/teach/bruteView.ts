// Teaching view 4: every first order triangulation of a small terrain, as
// thumbnails sorted by the objective (from terrain.enumerateAll()), the optimum
// first.
import { OBJECTIVE_IDS, type ObjectiveId, type Terrain } from 'hodt';
import { h } from '../ui/dom.ts';
import { formatValue, OBJECTIVE_HELP } from '../ui/objectiveHelp.ts';
import { EDGE_COLORS, EDGE_SHAPE_COLORS, EXTREMUM_COLORS, FLIPPED_COLOR, QUAD_COLOR, VERTEX_CLASS_COLORS, VERTEX_COLORS } from '../views/palette.ts';
import { withAlpha } from '../views/plan/planRenderer.ts';
import { fitTransform, toScreenX, toScreenY } from '../views/plan/planTransform.ts';
import { button, createPane, legend, paperLink, smallTerrain, type TeachContext, type TeachView } from './common.ts';
import { readStructure, trianglesOf, type QuadStructure } from './structure.ts';

/** Up to 2^10 = 1024 thumbnails. */
export const MAX_BRUTE_QUADS = 10;

interface State {
  terrain: Terrain;
  structure: QuadStructure;
  objective: ObjectiveId;
  sense: 'min' | 'max';
  /** Choices (as bit masks) sorted best first, with their values. */
  order: { mask: number; value: number }[];
  best: number;
}

export function createBruteView(ctx: TeachContext): TeachView {
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

  let active = false;
  let stale = true;
  let state: State | null = null;
  let message: string | null = null;
  let drawToken = 0;

  function update(): void {
    if (!active || !stale) return;
    stale = false;
    const terrain = ctx.terrain();
    const objective = ctx.settings().objective;
    const info = ctx.hodt.objectives.find((o) => o.id === objective)!;
    const m = terrain.numQuads;
    if (m > MAX_BRUTE_QUADS) {
      state = null;
      message = `This terrain has ${m} flippable quads: 2^${m} = ${(2 ** m).toLocaleString('en')} triangulations are too many to draw (at most 2^${MAX_BRUTE_QUADS}). Load a small terrain.`;
      render();
      return;
    }
    message = null;
    const structure = readStructure(terrain);
    const all = terrain.enumerateAll();
    const k = OBJECTIVE_IDS.indexOf(objective);
    const order = Array.from({ length: 1 << m }, (_, mask) => ({ mask, value: all[mask * OBJECTIVE_IDS.length + k]! }));
    const better = info.sense === 'min' ? 1 : -1;
    order.sort((a, b) => better * (a.value - b.value) || a.mask - b.mask);
    state = { terrain, structure, objective, sense: info.sense, order, best: order[0]!.value };
    render();
  }

  function render(): void {
    const my = ++drawToken;
    if (!state) {
      status.textContent = message ?? '';
      grid.replaceChildren();
      histogram.replaceChildren();
      return;
    }
    const s = state;
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
    const counts = new Map<number, number>();
    for (const x of s.order) counts.set(x.value, (counts.get(x.value) ?? 0) + 1);
    const distinct = [...counts.entries()];
    const top = Math.max(...distinct.map(([, c]) => c));
    histogram.replaceChildren(
      h('span', { class: 'muted' }, 'values, best first'),
      h(
        'div',
        { class: 'bars' },
        ...distinct.slice(0, 40).map(([v, c], i) => h('i', { style: `height: ${Math.max(4, (c / top) * 48)}px`, class: i === 0 ? 'best' : '', title: `${fmt(v)}: ${c} triangulation${c === 1 ? '' : 's'}` })),
      ),
    );
    const size = m <= 6 ? 150 : m <= 8 ? 118 : 92;
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

  return {
    id: 'brute',
    label: 'All triangulations',
    root,
    activate() {
      active = true;
      update();
    },
    deactivate() {
      active = false;
    },
    changed() {
      stale = true;
      update();
    },
    hooks() {
      return {
        message,
        objective: state?.objective ?? null,
        count: state?.order.length ?? 0,
        values: state?.order.map((x) => x.value) ?? [],
        choices: state?.order.map((x) => x.mask) ?? [],
        drawn: Number(grid.dataset.drawn ?? 0),
      };
    },
  };
}

function popcount(x: number): number {
  let c = 0;
  for (; x; x &= x - 1) c++;
  return c;
}

/** A triangulation as a thumbnail: flipped quads amber, edges by shape (red
 * convex, blue reflex), interior vertices by class (purple mixed) and extrema. */
function drawThumb(canvas: HTMLCanvasElement, terrain: Terrain, s: QuadStructure, mask: number): void {
  const c = canvas.getContext('2d')!;
  const size = canvas.width;
  const t = fitTransform(s.points, size, size, size * 0.07);
  const p = s.points;
  const choice = Uint8Array.from({ length: s.m }, (_, q) => (mask >> q) & 1);
  const tris = trianglesOf(s, choice);
  const m = terrain.measures(choice);
  const X = (v: number) => toScreenX(t, p[3 * v]!);
  const Y = (v: number) => toScreenY(t, p[3 * v + 1]!);
  c.clearRect(0, 0, size, size);
  const kept = new Path2D(), flipped = new Path2D(), all = new Path2D();
  for (let k = 0; k < tris.length / 3; k++) {
    const path = new Path2D();
    for (let j = 0; j < 3; j++) {
      const v = tris[3 * k + j]!;
      if (j === 0) path.moveTo(X(v), Y(v));
      else path.lineTo(X(v), Y(v));
    }
    path.closePath();
    all.addPath(path);
    const q = s.slotQuad[k]!;
    if (q >= 0) (choice[q] ? flipped : kept).addPath(path);
  }
  c.fillStyle = '#f6f7f5';
  c.fill(all);
  c.fillStyle = withAlpha(QUAD_COLOR, 0.18);
  c.fill(kept);
  c.fillStyle = withAlpha(FLIPPED_COLOR, 0.55);
  c.fill(flipped);
  // Edges by shape (each interior edge is drawn from both sides: same colour).
  c.lineCap = 'round';
  for (let shape = 0; shape < 4; shape++) {
    c.beginPath();
    for (let e = 0; e < tris.length; e++) {
      if (m.edgeShape[e] !== shape) continue;
      const u = tris[e]!, v = tris[e % 3 === 2 ? e - 2 : e + 1]!;
      c.moveTo(X(u), Y(u));
      c.lineTo(X(v), Y(v));
    }
    c.strokeStyle = EDGE_SHAPE_COLORS[shape]!;
    c.lineWidth = shape === 3 ? size / 90 : size / 130;
    c.stroke();
  }
  const r = size / 42;
  for (let v = 0; v < p.length / 3; v++) {
    const cls = m.vertexClass[v]!;
    if (cls === 4) continue;
    c.beginPath();
    c.arc(X(v), Y(v), m.extremum[v] ? r * 1.35 : r, 0, 2 * Math.PI);
    c.fillStyle = m.extremum[v] === 1 ? EXTREMUM_COLORS.minimum : m.extremum[v] === 2 ? EXTREMUM_COLORS.maximum : VERTEX_CLASS_COLORS[cls]!;
    c.fill();
    c.strokeStyle = '#fff';
    c.lineWidth = size / 200;
    c.stroke();
  }
}
