// Drawing of the 2-SAT search view: the terrain at a step of the search (forced
// quads, pairs over the threshold, the implication graph between quad centres
// coloured by strongly connected component, contradictions) and the number line
// of the binary search over the candidate values.
import { formatValue } from '../../ui/objectiveHelp.ts';
import { CRITICAL_COLOR, FLIPPED_COLOR, QUAD_COLOR } from '../../views/palette.ts';
import { withAlpha } from '../../views/plan/planRenderer.ts';
import { drawBackdrop, trianglePath, type FittedCanvas } from '../canvas.ts';
import { COMPONENT_COLORS } from '../common.ts';
import { trianglesOf, type QuadStructure } from '../structure.ts';
import { choiceAt, quadPairs, searchRows, testAt, type SatSearch } from './model.ts';

export const BLOCK_COLOR = '#c62828';
const SVG = 'http://www.w3.org/2000/svg';

/** The number line: the candidates in increasing order (evenly spaced), then a
 * row per step: the interval still open before it (blue) and the threshold it
 * tested (green yes, red no); the optimum marked at the end. */
export function drawLine(line: SVGSVGElement, s: SatSearch, pos: number): void {
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
  const upto = Math.min(pos, steps);
  searchRows(s).forEach(({ lo, hi, rank, satisfiable }, i) => {
    const y = rowY(i);
    const current = i + 1 === pos;
    const shown = i < upto;
    nodes.push(el('text', { x: 2, y: y + 3.5, 'font-size': 10, fill: shown ? '#1e2a26' : '#c3cac7', 'font-weight': current ? 700 : 400 }, String(i + 1)));
    nodes.push(el('rect', { x: x(lo) - 3, y: y - 4, width: Math.max(6, x(hi) - x(lo) + 6), height: 8, rx: 4, fill: shown ? 'rgba(31, 119, 180, 0.16)' : 'rgba(31, 119, 180, 0.05)' }));
    if (shown) {
      const color = satisfiable ? '#17804a' : BLOCK_COLOR;
      nodes.push(el('circle', { cx: x(rank), cy: y, r: current ? 5 : 3.8, fill: color, stroke: current ? '#111' : '#fff', 'stroke-width': current ? 1.6 : 1 }));
    }
  });
  if (pos > steps) {
    const y = rowY(steps);
    const cx = x(Math.max(0, s.search.candidates.indexOf(s.solution.value)));
    nodes.push(el('path', { d: `M${cx} ${y - 6} l5 9 h-10 z`, fill: '#111' }));
    nodes.push(el('text', { x: cx + (cx > 200 ? -8 : 8), y: y + 3, 'font-size': 10, 'font-weight': 700, 'text-anchor': cx > 200 ? 'end' : 'start', fill: '#111' }, `optimum ${fmt(s.solution.value)}`));
  }
  line.replaceChildren(...nodes);
}

export function drawSearch(c: CanvasRenderingContext2D, f: FittedCanvas, s: SatSearch, pos: number): void {
  const st = s.structure;
  const p = st.points;
  const n = s.search.tests.length;
  const a = testAt(s, pos);
  const choice = choiceAt(s, pos);
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
  if (pos > n && s.solution.critical) {
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

function quadSlots(st: QuadStructure): number[] {
  return Array.from(st.quadSlots).filter((k) => k >= 0);
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

