// Drawing of the Mixed vertices view: the triangulation's edges, each fan's
// quads with the diagonal it uses, the mixed vertices and the clause vertices.
import { VertexClass } from 'hodt';
import { centredLabels, drawQuad, screenPoints, tint, variableColor, type FittedCanvas } from '../canvas.ts';
import { sectorCorners } from './build.ts';
import type { MixedBuilt } from './model.ts';

export const MIXED = '#d62728';

export function drawMixed(c: CanvasRenderingContext2D, fc: FittedCanvas, b: MixedBuilt): void {
  const g = b.gadget;
  const p = g.points;
  const { X, Y } = screenPoints(fc, p);
  const choice = b.solution?.choice ?? null;
  const classes = b.terrain.measures(choice ?? undefined).vertexClass;
  // Every edge of the triangulation, thin, then the fans' quads on top.
  const tri = b.terrain.triangulation(choice ?? undefined).triangles;
  c.strokeStyle = 'rgba(60, 72, 68, 0.25)';
  c.lineWidth = 0.7;
  c.beginPath();
  for (let k = 0; k < tri.length; k += 3) {
    c.moveTo(X(tri[k]!), Y(tri[k]!));
    c.lineTo(X(tri[k + 1]!), Y(tri[k + 1]!));
    c.lineTo(X(tri[k + 2]!), Y(tri[k + 2]!));
    c.closePath();
  }
  c.stroke();
  g.fans.forEach((fan, i) => {
    const colour = variableColor(fan.variable);
    fan.inner.forEach((_, k) => {
      const q = b.map.quad[i]![k]!;
      const ccw = (choice ? choice[q] === 0 : true) === (b.map.delaunayCcw[i]![k] === 1);
      drawQuad(c, X, Y, sectorCorners(fan, k), { fill: tint(colour, 0.3), outline: '#777', diagonalAC: ccw, width: Math.max(1.5, fc.scale * 0.035) });
    });
  });
  const r = Math.max(2.2, Math.min(5, fc.scale * 0.07));
  for (let i = 0; i < p.length / 3; i++) {
    const role = g.roles[i]!;
    const mixed = classes[i] === VertexClass.Mixed;
    c.fillStyle = mixed ? MIXED : role === 'clause' || role === 'unit' ? '#17804a' : 'rgba(90, 100, 96, 0.6)';
    c.beginPath();
    c.arc(X(i), Y(i), mixed || role === 'clause' || role === 'unit' ? r : r * 0.7, 0, 2 * Math.PI);
    c.fill();
  }
  centredLabels(c, 600, Math.max(10, Math.min(13, fc.scale * 0.22)));
  // Clause labels just below their vertex.
  const labelled = new Map<number, string[]>();
  for (const cv of g.clauses) labelled.set(cv.point, [...(labelled.get(cv.point) ?? []), `C${cv.clause + 1}`]);
  for (const [i, names] of labelled) {
    c.fillStyle = classes[i] === VertexClass.Mixed ? MIXED : '#17804a';
    c.fillText(names.join(', '), X(i), fc.sy(p[3 * i + 1]! - 0.45));
  }
  for (const fan of g.fans) {
    c.fillStyle = variableColor(fan.variable);
    c.fillText(b.formula.names[fan.variable]!, fc.sx(fan.x), fc.sy(fan.y + 0.5));
  }
}
