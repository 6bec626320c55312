// Drawing of the Max degree view: the rows of cells with the diagonal each uses,
// the points coloured by their role and degree, the clause vertices' degrees.
import { centredLabels, drawQuad, screenPoints, tint, variableColor, type FittedCanvas } from '../canvas.ts';
import type { DegreeBuilt } from './model.ts';

export function drawDegree(c: CanvasRenderingContext2D, fc: FittedCanvas, b: DegreeBuilt): void {
  const g = b.gadget;
  const p = g.points;
  const { X, Y } = screenPoints(fc, p);
  const choice = b.solution?.choice ?? null;
  const degrees = b.terrain.measures(choice ?? undefined).degree;
  g.cells.forEach((cell, i) => {
    const v = cell.wire >= 0 ? g.wires[cell.wire]!.variable : -1;
    const q = b.map.quad[i]!;
    const rises = (choice ? choice[q] === 0 : true) === (b.map.delaunayRises[i] === 1); // sw-ne
    drawQuad(c, X, Y, cell.corners, {
      fill: v >= 0 ? tint(variableColor(v), 0.35) : 'rgba(120, 120, 120, 0.25)',
      outline: '#555',
      diagonalAC: rises,
      width: Math.max(1.5, fc.scale * 0.04),
    });
  });
  const r = Math.max(2, Math.min(5, fc.scale * 0.07));
  for (let i = 0; i < p.length / 3; i++) {
    const role = g.roles[i]!;
    const over = degrees[i]! > g.bound;
    c.fillStyle = over ? '#d62728' : role === 'clause' || role === 'unit' ? '#17804a' : role === 'pendant' ? 'rgba(90, 100, 96, 0.6)' : '#333';
    c.beginPath();
    c.arc(X(i), Y(i), role === 'pendant' && !over ? r * 0.6 : r, 0, 2 * Math.PI);
    c.fill();
  }
  centredLabels(c, 600, Math.max(10, Math.min(13, fc.scale * 0.22)));
  for (const cv of g.clauses) {
    const i = cv.point;
    const up = p[3 * i + 1]! > 0.4 ? -1 : 1;
    c.fillStyle = degrees[i]! > g.bound ? '#d62728' : '#17804a';
    c.fillText(`C${cv.clause + 1}: ${degrees[i]}`, X(i), Y(i) + up * fc.scale * 0.28);
  }
  for (const w of g.wires) {
    const first = g.cells[w.cells[0]!]!, last = g.cells[w.cells.at(-1)!]!;
    c.fillStyle = variableColor(w.variable);
    c.fillText(b.formula.names[w.variable]!, (fc.sx(first.x) + fc.sx(last.x + 1)) / 2, fc.sy(first.y + 1.55));
  }
}
