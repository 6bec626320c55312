// Drawing of the Hardness gadget view: the coating, each variable's pool and
// tentacles with the diagonal each cell uses, the clause edges and the labels.
import { EDGE_COLORS } from '../../views/palette.ts';
import { centredLabels, screenPoints, tint, variableColor, type FittedCanvas } from '../canvas.ts';
import { cellStates } from './check.ts';
import type { GadgetBuilt } from './model.ts';

export function drawGadget(c: CanvasRenderingContext2D, f: FittedCanvas, b: GadgetBuilt): void {
  const g = b.gadget;
  const p = g.points;
  const { X, Y } = screenPoints(f, p);
  // The coating: the lattice region, pale.
  c.fillStyle = '#eceeea';
  c.fillRect(f.sx(g.bounds.x0), f.sy(g.bounds.y1), (g.bounds.x1 - g.bounds.x0) * f.scale, (g.bounds.y1 - g.bounds.y0) * f.scale);
  c.fillStyle = 'rgba(90, 100, 96, 0.35)';
  const dot = Math.max(0.8, Math.min(1.6, f.scale * 0.08));
  for (let i = g.numLow; i < p.length / 3; i++) c.fillRect(X(i) - dot / 2, Y(i) - dot / 2, dot, dot);
  // Cells by variable, with their diagonal.
  const convex = b.solution ? cellStates(b.map, b.solution.choice) : g.cells.map((_, i) => b.map.delaunayIsConvex[i] === 1);
  const red = new Path2D(), blue = new Path2D(), outline = new Path2D(), skips = new Path2D();
  g.cells.forEach((cell, i) => {
    const [sw, se, ne, nw] = cell.corners;
    const path = new Path2D();
    path.moveTo(X(sw), Y(sw));
    path.lineTo(X(se), Y(se));
    path.lineTo(X(ne), Y(ne));
    path.lineTo(X(nw), Y(nw));
    path.closePath();
    c.fillStyle = tint(variableColor(cell.variable), cell.clause < 0 ? 0.3 : 0.5);
    c.fill(path);
    outline.addPath(path);
    if (cell.w > 1) skips.addPath(path);
    const target = convex[i] ? red : blue;
    if (convex[i]) {
      target.moveTo(X(sw), Y(sw));
      target.lineTo(X(ne), Y(ne));
    } else {
      target.moveTo(X(se), Y(se));
      target.lineTo(X(nw), Y(nw));
    }
  });
  c.strokeStyle = 'rgba(255, 255, 255, 0.9)';
  c.lineWidth = 1;
  c.stroke(outline);
  const w = Math.max(1, Math.min(2.2, f.scale * 0.12));
  c.lineWidth = w;
  c.strokeStyle = EDGE_COLORS.convex;
  c.stroke(red);
  c.strokeStyle = EDGE_COLORS.reflex;
  c.stroke(blue);
  c.setLineDash([4, 3]);
  c.strokeStyle = '#111';
  c.lineWidth = 1.4;
  c.stroke(skips);
  c.setLineDash([]);
  // Clause meeting edges.
  centredLabels(c, 700, Math.max(10, Math.min(14, f.scale * 0.7)));
  b.gadget.clauses.forEach((cl, k) => {
    const a = g.cells[cl.tentacles[0].cells.at(-1)!]!;
    const z = g.cells[cl.tentacles[1].cells.at(-1)!]!;
    const shared = a.corners.filter((v) => z.corners.includes(v));
    if (shared.length !== 2) return;
    const good = b.readback?.edgeConvex[k];
    c.strokeStyle = good === undefined ? '#333' : good ? '#17804a' : '#9aa19e';
    c.lineWidth = Math.max(3, f.scale * 0.28);
    c.lineCap = 'round';
    c.beginPath();
    c.moveTo(X(shared[0]!), Y(shared[0]!));
    c.lineTo(X(shared[1]!), Y(shared[1]!));
    c.stroke();
    const mx = (X(shared[0]!) + X(shared[1]!)) / 2;
    const my = (Y(shared[0]!) + Y(shared[1]!)) / 2 + (cl.page === 'top' ? -1 : 1) * f.scale * 1.4;
    label(c, `C${k + 1}`, mx, my, good === false ? '#6b716e' : '#17804a');
  });
  // Pool labels: variable = value.
  g.pools.forEach((pool) => {
    const v = pool.variable;
    const text = `${b.formula.names[v]}${b.readback ? ` = ${b.readback.assignment[v] ? 'T' : 'F'}` : ''}`;
    label(c, text, f.sx(pool.x0 + pool.w / 2), f.sy(pool.y0 + pool.h / 2), variableColor(v));
  });
}

function label(c: CanvasRenderingContext2D, text: string, x: number, y: number, color: string): void {
  const m = c.measureText(text);
  const pad = 4;
  const hgt = parseFloat(c.font.split(' ')[1]!) + 4;
  c.fillStyle = 'rgba(255, 255, 255, 0.92)';
  c.beginPath();
  c.roundRect(x - m.width / 2 - pad, y - hgt / 2, m.width + 2 * pad, hgt, 4);
  c.fill();
  c.strokeStyle = color;
  c.lineWidth = 1.2;
  c.stroke();
  c.fillStyle = color;
  c.fillText(text, x, y + 0.5);
}
