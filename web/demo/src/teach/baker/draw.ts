// Drawing of the Baker layers view: the quad graph (a dot per quad, joined when
// two quads share an edge) coloured by layer, the edges the shown shift cuts,
// and the flips of its triangulation.
import { FLIPPED_COLOR } from '../../views/palette.ts';
import { withAlpha } from '../../views/plan/planRenderer.ts';
import { drawBackdrop, layerColor, type FittedCanvas } from '../canvas.ts';
import { trianglesOf } from '../structure.ts';
import { choiceAt, isCut, shiftAt, type BakerState } from './model.ts';

export const CUT_COLOR = '#d62728';

export function drawLayers(c: CanvasRenderingContext2D, f: FittedCanvas, s: BakerState, pos: number): void {
  const st = s.structure;
  const p = st.points;
  const shift = shiftAt(s, pos);
  const choice = choiceAt(s, pos);
  drawBackdrop(c, f, p, trianglesOf(st, choice ?? new Uint8Array(st.m)), 0.25);
  // Quads filled by layer; flipped ones hatched amber.
  const layer = s.baker?.layer ?? new Uint32Array(st.m);
  const byLayer = Array.from({ length: Math.max(1, s.layers) }, () => new Path2D());
  const flipped = new Path2D();
  for (let q = 0; q < st.m; q++) {
    const path = byLayer[layer[q]!]!;
    const corners = [st.quads[4 * q]!, st.quads[4 * q + 2]!, st.quads[4 * q + 1]!, st.quads[4 * q + 3]!];
    for (const target of choice?.[q] ? [path, flipped] : [path]) {
      corners.forEach((v, j) => (j === 0 ? target.moveTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!)) : target.lineTo(f.sx(p[3 * v]!), f.sy(p[3 * v + 1]!))));
      target.closePath();
    }
  }
  byLayer.forEach((path, l) => {
    c.fillStyle = layerColor(l, Math.max(1, s.layers)).replace('rgb(', 'rgba(').replace(')', ', 0.42)');
    c.fill(path);
  });
  c.strokeStyle = withAlpha(FLIPPED_COLOR, 0.95);
  c.lineWidth = 2;
  c.stroke(flipped);
  // The quad graph.
  const cx = (q: number) => f.sx(st.centroid[2 * q]!);
  const cy = (q: number) => f.sy(st.centroid[2 * q + 1]!);
  const kept = new Path2D(), cut = new Path2D();
  for (const [q, r] of st.quadEdges) {
    const lo = Math.min(layer[q]!, layer[r]!), hi = Math.max(layer[q]!, layer[r]!);
    const target = shift !== null && isCut(lo, hi, shift, s.lambda!) ? cut : kept;
    target.moveTo(cx(q), cy(q));
    target.lineTo(cx(r), cy(r));
  }
  c.strokeStyle = 'rgba(30, 42, 38, 0.55)';
  c.lineWidth = 1.3;
  c.stroke(kept);
  c.setLineDash([5, 4]);
  c.strokeStyle = CUT_COLOR;
  c.lineWidth = 2.4;
  c.stroke(cut);
  c.setLineDash([]);
  const r = st.m > 600 ? 2.2 : 3.6;
  for (let q = 0; q < st.m; q++) {
    c.beginPath();
    c.arc(cx(q), cy(q), r, 0, 2 * Math.PI);
    c.fillStyle = layerColor(layer[q]!, Math.max(1, s.layers));
    c.fill();
    c.strokeStyle = '#fff';
    c.lineWidth = 1;
    c.stroke();
  }
}
