// A canvas that fills its container, keeps a data-to-screen transform fitted to a
// bounding box, and redraws on resize: the drawing surface of the teaching views;
// the state a view draws on it; and what the views' drawings share.
import { fitTransform, toScreenX, toScreenY, type PlanTransform } from '../views/plan/planTransform.ts';

export interface FittedCanvas {
  readonly canvas: HTMLCanvasElement;
  /** Data points (x, y, z per point) whose bounding box to fit. */
  fit(xyz: Float64Array, margin?: number): void;
  /** Asks for a redraw (next animation frame). */
  redraw(): void;
  sx(x: number): number;
  sy(y: number): number;
  readonly scale: number;
  /** Canvas size in CSS pixels. */
  readonly width: number;
  readonly height: number;
}

export function createFittedCanvas(container: HTMLElement, draw: (ctx: CanvasRenderingContext2D, c: FittedCanvas) => void, label: string): FittedCanvas {
  const canvas = document.createElement('canvas');
  canvas.className = 'teach-canvas';
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', label);
  container.appendChild(canvas);
  const ctx = canvas.getContext('2d')!;
  let box: Float64Array | null = null;
  let margin = 24;
  let t: PlanTransform = { scale: 1, ox: 0, oy: 0 };
  let queued = false;
  let w = 1, h = 1;
  const self: FittedCanvas = {
    canvas,
    fit(xyz, m = 24) {
      box = xyz;
      margin = m;
      self.redraw();
    },
    redraw() {
      if (queued) return;
      queued = true;
      requestAnimationFrame(paint);
    },
    sx: (x) => toScreenX(t, x),
    sy: (y) => toScreenY(t, y),
    get scale() {
      return t.scale;
    },
    get width() {
      return w;
    },
    get height() {
      return h;
    },
  };
  function paint(): void {
    queued = false;
    w = container.clientWidth || 1;
    h = container.clientHeight || 1;
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
    }
    if (box) t = fitTransform(box, w, h, margin);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, w, h);
    draw(ctx, self);
  }
  new ResizeObserver(() => self.redraw()).observe(container);
  return self;
}

/**
 * The state a view shows (null, if S allows it, while there is none yet), on a
 * fitted canvas in `container` (`draw`) and in its pane (`fill`, once the canvas
 * is asked to redraw); neither runs while the state is null. `set` replaces the
 * state and shows it; `render` shows it again (a step, a control of the view's own).
 */
export function createShownState<S>(
  container: HTMLElement,
  label: string,
  draw: (ctx: CanvasRenderingContext2D, c: FittedCanvas, s: NonNullable<S>) => void,
  fill: (s: NonNullable<S>) => void,
  initial: S,
) {
  let state = initial;
  const canvas = createFittedCanvas(container, (ctx, c) => state != null && draw(ctx, c, state), label);
  const render = (): void => {
    canvas.redraw();
    if (state != null) fill(state);
  };
  return {
    canvas,
    get state(): S {
      return state;
    },
    set(s: NonNullable<S>): void {
      state = s;
      render();
    },
    render,
  };
}

/** Where point i of xyz (x, y, z per point) is on the canvas. */
export function screenPoints(c: FittedCanvas, xyz: Float64Array): { X: (i: number) => number; Y: (i: number) => number } {
  return { X: (i) => c.sx(xyz[3 * i]!), Y: (i) => c.sy(xyz[3 * i + 1]!) };
}

/** Pale grey triangles by mean elevation and thin edges: the backdrop of a view. */
export function drawBackdrop(ctx: CanvasRenderingContext2D, c: FittedCanvas, points: Float64Array, triangles: ArrayLike<number>, edgeAlpha = 0.35): void {
  let zmin = Infinity, zmax = -Infinity;
  for (let i = 2; i < points.length; i += 3) (zmin = Math.min(zmin, points[i]!)), (zmax = Math.max(zmax, points[i]!));
  const LEVELS = 16;
  const levels = Array.from({ length: LEVELS }, () => new Path2D());
  const edges = new Path2D();
  for (let k = 0; k < triangles.length; k += 3) {
    let z = 0;
    const path = new Path2D();
    for (let j = 0; j < 3; j++) {
      const v = triangles[k + j]!;
      z += points[3 * v + 2]!;
      const x = c.sx(points[3 * v]!), y = c.sy(points[3 * v + 1]!);
      if (j === 0) path.moveTo(x, y);
      else path.lineTo(x, y);
    }
    path.closePath();
    const level = Math.min(LEVELS - 1, Math.floor(((z / 3 - zmin) / (zmax - zmin || 1)) * LEVELS));
    levels[level]!.addPath(path);
    edges.addPath(path);
  }
  levels.forEach((path, level) => {
    const g = Math.round(226 + (26 * (level + 0.5)) / LEVELS);
    ctx.fillStyle = `rgb(${g}, ${g + 1}, ${g})`;
    ctx.fill(path);
  });
  ctx.strokeStyle = `rgba(60, 72, 68, ${edgeAlpha})`;
  ctx.lineWidth = 0.7;
  ctx.stroke(edges);
}

/** A path of the given triangles (point indices, three per triangle). */
export function trianglePath(c: FittedCanvas, points: Float64Array, triangles: ArrayLike<number>, slots?: Iterable<number>): Path2D {
  const path = new Path2D();
  const add = (k: number) => {
    for (let j = 0; j < 3; j++) {
      const v = triangles[3 * k + j]!;
      const x = c.sx(points[3 * v]!), y = c.sy(points[3 * v + 1]!);
      if (j === 0) path.moveTo(x, y);
      else path.lineTo(x, y);
    }
    path.closePath();
  };
  if (slots) for (const k of slots) add(k);
  else for (let k = 0; k < triangles.length / 3; k++) add(k);
  return path;
}

/** A gadget's quad (a, b, c, d counterclockwise, canvas coordinates through x
 * and y): filled and outlined, with its chosen diagonal (ac or bd) drawn bold. */
export function drawQuad(
  c: CanvasRenderingContext2D,
  x: (i: number) => number,
  y: (i: number) => number,
  [a, b, cc, d]: readonly [number, number, number, number],
  style: { fill: string; outline: string; diagonalAC: boolean; width: number },
): void {
  c.beginPath();
  c.moveTo(x(a), y(a));
  c.lineTo(x(b), y(b));
  c.lineTo(x(cc), y(cc));
  c.lineTo(x(d), y(d));
  c.closePath();
  c.fillStyle = style.fill;
  c.fill();
  c.strokeStyle = style.outline;
  c.lineWidth = 1;
  c.stroke();
  const [from, to] = style.diagonalAC ? [a, cc] : [b, d];
  c.beginPath();
  c.moveTo(x(from), y(from));
  c.lineTo(x(to), y(to));
  c.strokeStyle = '#111';
  c.lineWidth = style.width;
  c.stroke();
}

/** A #rrggbb colour with an alpha. */
export function tint(hex: string, alpha: number): string {
  const v = parseInt(hex.slice(1), 16);
  return `rgba(${(v >> 16) & 255}, ${(v >> 8) & 255}, ${v & 255}, ${alpha})`;
}

const CATEGORICAL = ['#1f77b4', '#e6550d', '#31a354', '#9467bd', '#d62728', '#17becf', '#bcbd22', '#8c564b', '#e377c2', '#636363'] as const;

/** The colour of a gadget's variable v (the colours repeat past ten variables). */
export const variableColor = (v: number): string => CATEGORICAL[v % CATEGORICAL.length]!;

/** Labels from here on centred on their point, in system-ui of this weight and size. */
export function centredLabels(c: CanvasRenderingContext2D, weight: number, px: number): void {
  c.font = `${weight} ${px}px system-ui, sans-serif`;
  c.textAlign = 'center';
  c.textBaseline = 'middle';
}

/** Sequential colours for layers 0..count-1 (outer to inner). */
export function layerColor(layer: number, count: number): string {
  const t = count <= 1 ? 0 : layer / (count - 1);
  // From a deep blue at the hull to a warm yellow in the middle.
  const stops = [
    [37, 52, 148],
    [44, 127, 184],
    [65, 182, 196],
    [127, 205, 187],
    [199, 233, 180],
    [237, 221, 120],
  ];
  const x = t * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(x));
  const f = x - i;
  const [a, b] = [stops[i]!, stops[i + 1]!];
  return `rgb(${Math.round(a[0]! + f * (b[0]! - a[0]!))}, ${Math.round(a[1]! + f * (b[1]! - a[1]!))}, ${Math.round(a[2]! + f * (b[2]! - a[2]!))})`;
}
