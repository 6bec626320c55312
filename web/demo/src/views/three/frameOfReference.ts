/**
 * Data to world coordinates of the 3D view: x and y relative to the centre of
 * the points (so Float32 positions stay precise for UTM-size coordinates), heights
 * from the lowest point, exaggerated so the relief reads on flat terrains.
 */
export interface FrameOfReference {
  cx: number;
  cy: number;
  z0: number;
  exaggeration: number;
  /** Horizontal extent (largest side of the bounding box), in data units. */
  extent: number;
}

/** The frame of the points; `exaggeration` (if given) replaces the automatic one. */
export function frameOfReference(xyz: Float64Array, exaggeration: number | null = null): FrameOfReference {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity, z0 = Infinity, z1 = -Infinity;
  for (let i = 0; i < xyz.length; i += 3) {
    x0 = Math.min(x0, xyz[i]!);
    x1 = Math.max(x1, xyz[i]!);
    y0 = Math.min(y0, xyz[i + 1]!);
    y1 = Math.max(y1, xyz[i + 1]!);
    z0 = Math.min(z0, xyz[i + 2]!);
    z1 = Math.max(z1, xyz[i + 2]!);
  }
  const extent = Math.max(x1 - x0, y1 - y0) || 1;
  const relief = z1 - z0;
  // Aim for relief of about 30% of the extent; never flatten a terrain that is
  // already that steep, only steep ones beyond the extent itself.
  let automatic = relief > 0 ? (0.3 * extent) / relief : 1;
  if (relief <= extent) automatic = Math.max(1, automatic);
  return { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, z0, exaggeration: exaggeration ?? automatic, extent };
}

/** World positions (Float32) of the points. */
export function worldPositions(xyz: Float64Array, f: FrameOfReference): Float32Array {
  const out = new Float32Array(xyz.length);
  for (let i = 0; i < xyz.length; i += 3) {
    out[i] = xyz[i]! - f.cx;
    out[i + 1] = xyz[i + 1]! - f.cy;
    out[i + 2] = (xyz[i + 2]! - f.z0) * f.exaggeration;
  }
  return out;
}
