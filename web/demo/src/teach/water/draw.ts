// Drawing of the Water view: the triangulation faint, each triangle in the
// colour of the basin most of its corners drain to, the flow lines wider with
// log(accumulation), pits (red) and outlets (blue).
import { withAlpha } from '../../views/plan/planRenderer.ts';
import { screenPoints, trianglePath, type FittedCanvas } from '../canvas.ts';
import { COMPONENT_COLORS } from '../common.ts';
import { basinSlot, flowWidth, type WaterNetwork } from './model.ts';

export const FLOW_COLOR = '#0b4f8a';
export const PIT_COLOR = '#c62828';
export const OUTLET_COLOR = '#1565c0';

/** The basin of at least two of the triangle's corners, or -1. */
function majorityBasin(w: WaterNetwork, t: number): number {
  const [a, b, c] = [w.basin[w.triangles[3 * t]!]!, w.basin[w.triangles[3 * t + 1]!]!, w.basin[w.triangles[3 * t + 2]!]!];
  return a === b || a === c ? a : b === c ? b : -1;
}

export function drawWater(c: CanvasRenderingContext2D, f: FittedCanvas, w: WaterNetwork, p: Float64Array): void {
  const { X, Y } = screenPoints(f, p);
  const slots = COMPONENT_COLORS.length;
  // Basins: one path per colour slot.
  const fills = Array.from({ length: slots }, () => [] as number[]);
  const mixed: number[] = [];
  for (let t = 0; t < w.triangles.length / 3; t++) {
    const slot = basinSlot(majorityBasin(w, t), slots);
    (slot < 0 ? mixed : fills[slot]!).push(t);
  }
  fills.forEach((ts, slot) => {
    c.fillStyle = withAlpha(COMPONENT_COLORS[slot]!, 0.3);
    c.fill(trianglePath(f, p, w.triangles, ts));
  });
  c.fillStyle = '#f1f3f2';
  c.fill(trianglePath(f, p, w.triangles, mixed));
  c.strokeStyle = 'rgba(60, 72, 68, 0.22)';
  c.lineWidth = 0.6;
  c.stroke(trianglePath(f, p, w.triangles));
  // Flow lines, thin first so the main streams lie on top.
  const order = Array.from({ length: w.accumulation.length }, (_, s) => s).sort((a, b) => w.accumulation[a]! - w.accumulation[b]!);
  c.strokeStyle = FLOW_COLOR;
  c.lineCap = 'round';
  for (const s of order) {
    const u = w.segments[2 * s]!, v = w.segments[2 * s + 1]!;
    c.beginPath();
    c.moveTo(X(u), Y(u));
    c.lineTo(X(v), Y(v));
    c.lineWidth = flowWidth(w.accumulation[s]!, w.maxAccumulation);
    c.stroke();
  }
  // Where water ends: pits (red dots) and outlets (blue squares).
  c.lineWidth = 1.2;
  c.strokeStyle = '#fff';
  for (const v of w.outlets) {
    c.fillStyle = OUTLET_COLOR;
    c.fillRect(X(v) - 3.5, Y(v) - 3.5, 7, 7);
    c.strokeRect(X(v) - 3.5, Y(v) - 3.5, 7, 7);
  }
  for (const v of w.pits) {
    c.beginPath();
    c.arc(X(v), Y(v), 4.5, 0, 2 * Math.PI);
    c.fillStyle = PIT_COLOR;
    c.fill();
    c.stroke();
  }
}
