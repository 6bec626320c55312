// Drawing of the "All triangulations" view: one triangulation as a thumbnail.
import type { Terrain } from 'hodt';
import { EDGE_SHAPE_COLORS, EXTREMUM_COLORS, FLIPPED_COLOR, QUAD_COLOR, VERTEX_CLASS_COLORS } from '../../views/palette.ts';
import { withAlpha } from '../../views/plan/planRenderer.ts';
import { fitTransform, toScreenX, toScreenY } from '../../views/plan/planTransform.ts';
import { trianglesOf, type QuadStructure } from '../structure.ts';

/** A triangulation as a thumbnail: flipped quads amber, edges by shape (red
 * convex, blue reflex), interior vertices by class (purple mixed) and extrema. */
export function drawThumb(canvas: HTMLCanvasElement, terrain: Terrain, s: QuadStructure, mask: number): void {
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
