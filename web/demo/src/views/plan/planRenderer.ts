import type { Analysis } from '../../app/analysis.ts';
import { criticalTriangles } from '../../app/criticalTriangles.ts';
import {
  CRITICAL_COLOR,
  EDGE_SHAPE_COLORS,
  EXTREMUM_COLORS,
  FLIPPED_COLOR,
  OUTSIDE_COLOR,
  QUAD_COLOR,
  SELECTION_COLOR,
  USEFUL_COLOR,
  VERTEX_CLASS_COLORS,
} from '../palette.ts';
import { toScreenX, toScreenY, type PlanTransform } from './planTransform.ts';

export interface PlanDrawOptions {
  selected: number | null;
  hovered: number | null;
  /** Useful order-k edges to draw (pairs of point indices), or null. */
  useful: Uint32Array | null;
}

/**
 * Draws the plan (top) view: triangles in pale grey by mean elevation, flippable quads
 * (teal) and flipped ones (amber, with the Delaunay diagonal they replaced
 * dashed), the critical pair (pink outline), triangles outside the domain
 * (dark grey), edges coloured by shape, vertices
 * coloured by class, triangles on local minima and maxima, and the selection.
 */
export function drawPlan(ctx: CanvasRenderingContext2D, a: Analysis, t: PlanTransform, o: PlanDrawOptions): void {
  const { points, triangles } = a;
  const n = points.length / 3;
  const sx = new Float64Array(n);
  const sy = new Float64Array(n);
  let zmin = Infinity;
  let zmax = -Infinity;
  for (let i = 0; i < n; i++) {
    sx[i] = toScreenX(t, points[3 * i]!);
    sy[i] = toScreenY(t, points[3 * i + 1]!);
    zmin = Math.min(zmin, points[3 * i + 2]!);
    zmax = Math.max(zmax, points[3 * i + 2]!);
  }
  const numTriangles = triangles.length / 3;
  // Shapes are batched into one path per colour: a few dozen draw calls in all.
  const addTriangle = (path: Path2D, k: number) => {
    const a0 = triangles[3 * k]!, a1 = triangles[3 * k + 1]!, a2 = triangles[3 * k + 2]!;
    path.moveTo(sx[a0]!, sy[a0]!);
    path.lineTo(sx[a1]!, sy[a1]!);
    path.lineTo(sx[a2]!, sy[a2]!);
    path.closePath();
  };

  // Elevation as a faint grey in 24 steps (darker is lower): the colours are for
  // the overlays.
  const LEVELS = 24;
  const levels = Array.from({ length: LEVELS }, () => new Path2D());
  for (let k = 0; k < numTriangles; k++) {
    let z = 0;
    for (let j = 0; j < 3; j++) z += points[3 * triangles[3 * k + j]! + 2]!;
    const t = (z / 3 - zmin) / (zmax - zmin || 1);
    addTriangle(levels[Math.min(LEVELS - 1, Math.floor(t * LEVELS))]!, k);
  }
  ctx.lineJoin = 'round';
  ctx.lineWidth = 0.6;
  levels.forEach((path, level) => {
    const grey = Math.round(212 + (40 * (level + 0.5)) / LEVELS);
    ctx.fillStyle = ctx.strokeStyle = `rgb(${grey}, ${grey + 1}, ${grey})`;
    ctx.fill(path);
    ctx.stroke(path); // closes hairline gaps between triangles
  });

  // Flippable and flipped quads.
  const kept = new Path2D();
  const flipped = new Path2D();
  for (let k = 0; k < numTriangles; k++) {
    const q = a.quadOfTriangle[k]!;
    if (q >= 0) addTriangle(a.choice[q] ? flipped : kept, k);
    else if (a.changed?.[k]) addTriangle(flipped, k); // not a Delaunay triangle (order k >= 2)
  }
  ctx.fillStyle = withAlpha(QUAD_COLOR, 0.28);
  ctx.fill(kept);
  ctx.fillStyle = withAlpha(FLIPPED_COLOR, 0.55);
  ctx.fill(flipped);

  // Critical pair of a min-max objective.
  const critical = new Path2D();
  for (const k of criticalTriangles(a)) addTriangle(critical, k);
  ctx.fillStyle = withAlpha(CRITICAL_COLOR, 0.35);
  ctx.fill(critical);

  // Outside the domain: not measured, so drawn over whatever they would show.
  const outside = new Path2D();
  for (let k = 0; k < numTriangles; k++) if (a.inside[k] === 0) addTriangle(outside, k);
  ctx.fillStyle = withAlpha(OUTSIDE_COLOR, 0.6);
  ctx.fill(outside);

  // Useful order-k edges: a faint violet halo under the edges of the shown
  // triangulation, and violet lines for the others (drawn after the edges).
  let unused: Path2D | null = null;
  if (o.useful) {
    const key = (u: number, v: number) => (u < v ? u * n + v : v * n + u);
    const shown = new Set<number>();
    for (let e = 0; e < triangles.length; e++) shown.add(key(triangles[e]!, triangles[e % 3 === 2 ? e - 2 : e + 1]!));
    const halo = new Path2D();
    unused = new Path2D();
    for (let i = 0; i < o.useful.length; i += 2) {
      const u = o.useful[i]!, v = o.useful[i + 1]!;
      const path = shown.has(key(u, v)) ? halo : unused;
      path.moveTo(sx[u]!, sy[u]!);
      path.lineTo(sx[v]!, sy[v]!);
    }
    ctx.strokeStyle = withAlpha(USEFUL_COLOR, 0.28);
    ctx.lineWidth = n > 800 ? 2.5 : 4.5;
    ctx.stroke(halo);
  }

  // Edges by shape.
  const edgeWidth = n > 3000 ? 0.6 : n > 800 ? 0.9 : 1.4;
  ctx.lineCap = 'round';
  for (let shape = 0; shape < 4; shape++) {
    ctx.beginPath();
    for (let e = 0; e < triangles.length; e++) {
      if (a.halfedges[e]! > e || a.edgeShape[e] !== shape) continue;
      const u = triangles[e]!;
      const v = triangles[e % 3 === 2 ? e - 2 : e + 1]!;
      ctx.moveTo(sx[u]!, sy[u]!);
      ctx.lineTo(sx[v]!, sy[v]!);
    }
    ctx.strokeStyle = EDGE_SHAPE_COLORS[shape]!;
    ctx.lineWidth = shape === 3 ? edgeWidth + 0.8 : edgeWidth;
    ctx.stroke();
  }

  if (unused) {
    ctx.strokeStyle = withAlpha(USEFUL_COLOR, 0.85);
    ctx.lineWidth = n > 800 ? 0.8 : 1.2;
    ctx.stroke(unused);
  }

  // The Delaunay diagonal a flipped quad gave up, dashed.
  ctx.beginPath();
  for (let q = 0; q < a.choice.length; q++) {
    if (!a.choice[q]) continue;
    const u = a.quads[4 * q]!;
    const v = a.quads[4 * q + 1]!;
    ctx.moveTo(sx[u]!, sy[u]!);
    ctx.lineTo(sx[v]!, sy[v]!);
  }
  ctx.setLineDash([3, 3]);
  ctx.strokeStyle = 'rgba(60, 40, 0, 0.55)';
  ctx.lineWidth = 1;
  ctx.stroke();
  ctx.setLineDash([]);

  // Critical pair outline on top of the edges.
  ctx.strokeStyle = CRITICAL_COLOR;
  ctx.lineWidth = 2.2;
  ctx.stroke(critical);

  // Vertices by class, extrema as triangles.
  const r = n > 3000 ? 1.6 : n > 800 ? 2.4 : 3.6;
  const dots = VERTEX_CLASS_COLORS.map(() => new Path2D());
  const pits = new Path2D();
  const peaks = new Path2D();
  const tri = r * 2.2;
  for (let i = 0; i < n; i++) {
    const kind = a.extremum[i];
    if (kind) {
      const dir = kind === 1 ? 1 : -1; // a minimum points down (screen y grows down)
      const path = kind === 1 ? pits : peaks;
      path.moveTo(sx[i]!, sy[i]! + dir * tri);
      path.lineTo(sx[i]! - tri * 0.95, sy[i]! - dir * tri * 0.65);
      path.lineTo(sx[i]! + tri * 0.95, sy[i]! - dir * tri * 0.65);
      path.closePath();
      continue;
    }
    const c = a.vertexClass[i]!;
    const path = dots[c];
    if (!path) continue;
    const radius = c === 4 ? r * 0.75 : r;
    path.moveTo(sx[i]! + radius, sy[i]!);
    path.arc(sx[i]!, sy[i]!, radius, 0, Math.PI * 2);
  }
  ctx.lineWidth = 1;
  ctx.strokeStyle = 'rgba(255, 255, 255, 0.9)';
  dots.forEach((path, c) => {
    ctx.fillStyle = VERTEX_CLASS_COLORS[c]!;
    ctx.stroke(path);
    ctx.fill(path);
  });
  ctx.lineWidth = 1.4;
  ctx.strokeStyle = '#fff';
  for (const [path, color] of [
    [pits, EXTREMUM_COLORS.minimum],
    [peaks, EXTREMUM_COLORS.maximum],
  ] as const) {
    ctx.stroke(path);
    ctx.fillStyle = color;
    ctx.fill(path);
  }

  for (const [i, width, color] of [
    [o.hovered, 1.5, 'rgba(17, 17, 17, 0.55)'],
    [o.selected, 2.5, SELECTION_COLOR],
  ] as const) {
    if (i === null || i >= n) continue;
    ctx.beginPath();
    ctx.arc(sx[i]!, sy[i]!, r + 5, 0, Math.PI * 2);
    ctx.strokeStyle = color;
    ctx.lineWidth = width;
    ctx.stroke();
  }
}

export function withAlpha(hex: string, alpha: number): string {
  const v = parseInt(hex.slice(1), 16);
  return `rgba(${(v >> 16) & 255}, ${(v >> 8) & 255}, ${v & 255}, ${alpha})`;
}
