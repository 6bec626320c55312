// Drawing of one pane of the Water view: the triangulation faint, each triangle
// in the colour of the basin most of its corners drain to, the flow lines wider
// with log(accumulation), pits (red) and outlets (blue squares). The colours and
// widths are waterStyle.js, which the README's drainage figure draws with too.
import { withAlpha } from '../../views/plan/planRenderer.ts';
import { screenPoints, trianglePath, type FittedCanvas } from '../canvas.ts';
import type { WaterNetwork } from './model.ts';
import { BASIN_COLORS, BASIN_OPACITY, FLOW_COLOR, flowWidth, majorityBasin, NO_BASIN_COLOR, OUTLET_COLOR, PIT_COLOR } from './waterStyle.js';

/** Draws network w of points p; `slots` colour a basin by its pit or outlet. */
export function drawWater(c: CanvasRenderingContext2D, f: FittedCanvas, w: WaterNetwork, p: Float64Array, slots: Int32Array): void {
  const { X, Y } = screenPoints(f, p);
  // Basins: one path per colour slot.
  const fills = BASIN_COLORS.map(() => [] as number[]);
  const mixed: number[] = [];
  for (let t = 0; t < w.triangles.length / 3; t++) {
    const root = majorityBasin(w.triangles, w.basin, t);
    const slot = root < 0 ? -1 : slots[root]!;
    (slot < 0 ? mixed : fills[slot]!).push(t);
  }
  fills.forEach((ts, slot) => {
    c.fillStyle = withAlpha(BASIN_COLORS[slot]!, BASIN_OPACITY);
    c.fill(trianglePath(f, p, w.triangles, ts));
  });
  c.fillStyle = NO_BASIN_COLOR;
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
