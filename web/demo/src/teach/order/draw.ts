// Drawing of the Order k view: the regions of order k (a colour each where
// there is a choice, with their numbers of k-OD triangulations), the useful and
// fixed edges, the optimum's edges that Delaunay lacks, and the pits.
import { hasChoice, triangulationsMark } from '../../app/regionCount.ts';
import { FLIPPED_COLOR } from '../../views/palette.ts';
import { withAlpha } from '../../views/plan/planRenderer.ts';
import { centredLabels, screenPoints, type FittedCanvas } from '../canvas.ts';
import { COMPONENT_COLORS } from '../common.ts';
import { pitsGone, splitByDelaunay, type OrderState } from './model.ts';

export const FIXED_COLOR = '#1e2a26';
export const MINIMUM_COLOR = '#c62828';

export function drawRegions(c: CanvasRenderingContext2D, f: FittedCanvas, s: OrderState, p: Float64Array): void {
  const r = s.explanation?.regions;
  if (!r) return;
  const { X, Y } = screenPoints(f, p);
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
  const useful = pathOf(r.useful, X, Y);
  c.setLineDash([3, 3]);
  c.strokeStyle = 'rgba(110, 122, 118, 0.55)';
  c.lineWidth = 0.8;
  c.stroke(useful);
  c.setLineDash([]);
  const edges = splitByDelaunay(r.triangles, s.explanation!.solution.triangles);
  const chosen = pathOf(edges.kept, X, Y), changed = pathOf(edges.changed, X, Y);
  c.strokeStyle = 'rgba(40, 50, 46, 0.35)';
  c.lineWidth = 0.8;
  c.stroke(chosen);
  c.strokeStyle = withAlpha(FLIPPED_COLOR, 0.95);
  c.lineWidth = 2.2;
  c.stroke(changed);
  const fixed = pathOf(r.fixed, X, Y);
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
    centredLabels(c, 600, 11);
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
  for (const v of pitsGone(s)) {
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

/** Segments (pairs of point indices) as one path. */
function pathOf(pairs: ArrayLike<number>, X: (v: number) => number, Y: (v: number) => number): Path2D {
  const path = new Path2D();
  for (let i = 0; i < pairs.length; i += 2) {
    path.moveTo(X(pairs[i]!), Y(pairs[i]!));
    path.lineTo(X(pairs[i + 1]!), Y(pairs[i + 1]!));
  }
  return path;
}
