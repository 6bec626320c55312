/** Data (x, y; y north) to canvas pixels (y down) of the plan view: a uniform
 * scale and an offset, with fitting, zooming about a point and panning. */
export interface PlanTransform {
  scale: number;
  /** Screen position of data (0, 0). */
  ox: number;
  oy: number;
}

export const toScreenX = (t: PlanTransform, x: number) => t.ox + x * t.scale;
export const toScreenY = (t: PlanTransform, y: number) => t.oy - y * t.scale;
export const toDataX = (t: PlanTransform, sx: number) => (sx - t.ox) / t.scale;
export const toDataY = (t: PlanTransform, sy: number) => (t.oy - sy) / t.scale;

/** The transform showing all points in a width x height canvas with a margin. */
export function fitTransform(xyz: Float64Array, width: number, height: number, margin = 28): PlanTransform {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (let i = 0; i < xyz.length; i += 3) {
    x0 = Math.min(x0, xyz[i]!);
    x1 = Math.max(x1, xyz[i]!);
    y0 = Math.min(y0, xyz[i + 1]!);
    y1 = Math.max(y1, xyz[i + 1]!);
  }
  if (!Number.isFinite(x0)) return { scale: 1, ox: width / 2, oy: height / 2 };
  const w = Math.max(x1 - x0, 1e-12);
  const h = Math.max(y1 - y0, 1e-12);
  const scale = Math.min((width - 2 * margin) / w, (height - 2 * margin) / h);
  return {
    scale,
    ox: width / 2 - ((x0 + x1) / 2) * scale,
    oy: height / 2 + ((y0 + y1) / 2) * scale,
  };
}

/** Zooms by factor keeping the data point under (sx, sy) in place. */
export function zoomAt(t: PlanTransform, sx: number, sy: number, factor: number): PlanTransform {
  return { scale: t.scale * factor, ox: sx - (sx - t.ox) * factor, oy: sy - (sy - t.oy) * factor };
}

export function panBy(t: PlanTransform, dx: number, dy: number): PlanTransform {
  return { scale: t.scale, ox: t.ox + dx, oy: t.oy + dy };
}
