import type { Analysis } from '../../app/analysis.ts';
import { describeVertex } from '../../app/describeVertex.ts';
import { drawPlan } from './planRenderer.ts';
import { fitTransform, panBy, toDataX, toDataY, toScreenX, toScreenY, zoomAt, type PlanTransform } from './planTransform.ts';

/** What the plan view asks of the page; the page decides what an edit means. */
export interface PlanHandlers {
  select(index: number | null): void;
  /** Click on empty ground: add a point there. */
  add(x: number, y: number): void;
  /** A drag in progress (live preview) and its end (commit). In lift mode
   * (Shift held at the start) x and y stay and z follows the vertical motion. */
  drag(index: number, x: number, y: number, z: number): void;
  dragEnd(index: number, x: number, y: number, z: number): void;
}

export interface PlanView {
  show(a: Analysis): void;
  select(index: number | null): void;
  /** Useful order-k edges to draw (pairs of point indices), or null for none. */
  setUseful(edges: Uint32Array | null): void;
  /** Fits all points in the view. */
  fit(): void;
  /** Canvas pixel position (CSS pixels, relative to the canvas) of a data point. */
  toScreen(x: number, y: number): { x: number; y: number };
  readonly canvas: HTMLCanvasElement;
}

const PICK_RADIUS = 10; // CSS pixels
const CLICK_SLOP = 4;

export function createPlanView(container: HTMLElement, handlers: PlanHandlers): PlanView {
  const canvas = document.createElement('canvas');
  canvas.className = 'plan-canvas';
  canvas.tabIndex = 0;
  canvas.setAttribute('aria-label', 'Plan view: click to add a point, drag a point to move it, Shift+drag to change its height');
  container.appendChild(canvas);
  const ctx = canvas.getContext('2d')!;
  const tip = document.createElement('div');
  tip.className = 'plan-tip';
  tip.hidden = true;
  container.appendChild(tip);
  /** The hovered point's class and height next to the cursor. */
  const showTip = (i: number | null, at?: { x: number; y: number }) => {
    tip.hidden = i === null || !analysis || !at;
    if (tip.hidden) return;
    tip.textContent = describeVertex(analysis!, i!);
    const left = Math.min(at!.x + 14, container.clientWidth - tip.offsetWidth - 6);
    tip.style.transform = `translate(${Math.max(4, left)}px, ${at!.y + 16}px)`;
  };

  let analysis: Analysis | null = null;
  let transform: PlanTransform = { scale: 1, ox: 0, oy: 0 };
  let fitted = false;
  /** The user zoomed or panned: keep their view on resize. */
  let adjusted = false;
  let selected: number | null = null;
  let hovered: number | null = null;
  let useful: Uint32Array | null = null;
  let queued = false;

  const size = () => ({ w: container.clientWidth || 1, h: container.clientHeight || 1 });
  const draw = () => {
    queued = false;
    const { w, h } = size();
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, w, h);
    if (analysis) drawPlan(ctx, analysis, transform, { selected, hovered, useful });
  };
  const redraw = () => {
    if (queued) return;
    queued = true;
    requestAnimationFrame(draw);
  };
  const fit = () => {
    if (!analysis) return;
    const { w, h } = size();
    transform = fitTransform(analysis.points, w, h);
    fitted = container.clientWidth > 0;
    adjusted = false;
    redraw();
  };
  new ResizeObserver(() => (fitted && adjusted ? redraw() : fit())).observe(container);

  /** The vertex within PICK_RADIUS of a canvas position, nearest first. */
  const pick = (px: number, py: number): number | null => {
    if (!analysis) return null;
    const p = analysis.points;
    let best: number | null = null;
    let bestD = PICK_RADIUS * PICK_RADIUS;
    for (let i = 0; i < p.length / 3; i++) {
      const dx = toScreenX(transform, p[3 * i]!) - px;
      const dy = toScreenY(transform, p[3 * i + 1]!) - py;
      const d = dx * dx + dy * dy;
      if (d <= bestD) {
        bestD = d;
        best = i;
      }
    }
    return best;
  };
  const local = (e: PointerEvent | WheelEvent) => {
    const r = canvas.getBoundingClientRect();
    return { x: e.clientX - r.left, y: e.clientY - r.top };
  };

  type Gesture =
    | { kind: 'vertex'; index: number; lift: boolean; start: { x: number; y: number }; z0: number; moved: boolean }
    | { kind: 'ground'; start: { x: number; y: number }; last: { x: number; y: number }; moved: boolean };
  let gesture: Gesture | null = null;

  const dragTarget = (g: Extract<Gesture, { kind: 'vertex' }>, at: { x: number; y: number }) => {
    const p = analysis!.points;
    const i = g.index;
    if (g.lift) {
      // Vertical motion changes the height: the full relief over 200 pixels.
      let zmin = Infinity, zmax = -Infinity;
      for (let k = 2; k < p.length; k += 3) {
        zmin = Math.min(zmin, p[k]!);
        zmax = Math.max(zmax, p[k]!);
      }
      const perPixel = (zmax - zmin || 1) / 200;
      return { x: p[3 * i]!, y: p[3 * i + 1]!, z: g.z0 + (g.start.y - at.y) * perPixel };
    }
    return { x: toDataX(transform, at.x), y: toDataY(transform, at.y), z: p[3 * i + 2]! };
  };

  canvas.addEventListener('pointerdown', (e) => {
    if (e.button !== 0 || !analysis) return;
    canvas.focus();
    canvas.setPointerCapture(e.pointerId);
    const at = local(e);
    const index = pick(at.x, at.y);
    if (index !== null) {
      gesture = { kind: 'vertex', index, lift: e.shiftKey, start: at, z0: analysis.points[3 * index + 2]!, moved: false };
      selected = index;
      handlers.select(index);
      redraw();
    } else {
      gesture = { kind: 'ground', start: at, last: at, moved: false };
    }
  });
  canvas.addEventListener('pointermove', (e) => {
    const at = local(e);
    if (!gesture) {
      const h = pick(at.x, at.y);
      canvas.style.cursor = h !== null ? (e.shiftKey ? 'ns-resize' : 'grab') : 'crosshair';
      showTip(h, at);
      if (h !== hovered) {
        hovered = h;
        redraw();
      }
      return;
    }
    showTip(null);
    const far = Math.hypot(at.x - gesture.start.x, at.y - gesture.start.y) > CLICK_SLOP;
    if (gesture.kind === 'vertex') {
      if (!gesture.moved && !far) return;
      gesture.moved = true;
      canvas.style.cursor = gesture.lift ? 'ns-resize' : 'grabbing';
      const p = dragTarget(gesture, at);
      handlers.drag(gesture.index, p.x, p.y, p.z);
    } else {
      if (!gesture.moved && !far) return;
      gesture.moved = true;
      canvas.style.cursor = 'move';
      transform = panBy(transform, at.x - gesture.last.x, at.y - gesture.last.y);
      adjusted = true;
      gesture.last = at;
      redraw();
    }
  });
  const finish = (e: PointerEvent, cancelled: boolean) => {
    const g = gesture;
    gesture = null;
    if (!g || !analysis) return;
    const at = local(e);
    if (g.kind === 'vertex') {
      if (g.moved) {
        const p = cancelled ? { x: analysis.points[3 * g.index]!, y: analysis.points[3 * g.index + 1]!, z: g.z0 } : dragTarget(g, at);
        handlers.dragEnd(g.index, p.x, p.y, p.z);
      }
    } else if (!g.moved && !cancelled) {
      handlers.add(toDataX(transform, at.x), toDataY(transform, at.y));
    }
    canvas.style.cursor = 'crosshair';
  };
  canvas.addEventListener('pointerup', (e) => finish(e, false));
  canvas.addEventListener('pointercancel', (e) => finish(e, true));
  canvas.addEventListener('pointerleave', () => {
    showTip(null);
    if (hovered !== null && !gesture) {
      hovered = null;
      redraw();
    }
  });
  canvas.addEventListener(
    'wheel',
    (e) => {
      e.preventDefault();
      const at = local(e);
      transform = zoomAt(transform, at.x, at.y, Math.exp(-e.deltaY * 0.0015));
      adjusted = true;
      redraw();
    },
    { passive: false },
  );

  return {
    canvas,
    show(a) {
      const first = analysis === null;
      analysis = a;
      if (selected !== null && selected >= a.points.length / 3) selected = null;
      if (hovered !== null && hovered >= a.points.length / 3) hovered = null;
      if (first || !fitted) fit();
      else redraw();
    },
    select(index) {
      selected = index;
      redraw();
    },
    setUseful(edges) {
      useful = edges;
      redraw();
    },
    fit,
    toScreen(x, y) {
      return { x: toScreenX(transform, x), y: toScreenY(transform, y) };
    },
  };
}
