/** A regular grid of heights (a DEM): row-major values, row 0 at the top (north). */
export interface HeightGrid {
  width: number;
  height: number;
  values: ArrayLike<number>;
  /** Ground distance between neighbouring samples. */
  spacing: number;
}

/** Extent of the grid in ground units: x in [0, sizeX], y in [0, sizeY]. */
export function gridSize(grid: HeightGrid): { sizeX: number; sizeY: number } {
  return { sizeX: (grid.width - 1) * grid.spacing, sizeY: (grid.height - 1) * grid.spacing };
}

/** Bilinearly interpolated height at ground position (x, y); y grows northwards. */
export function heightAt(grid: HeightGrid, x: number, y: number): number {
  const { width, height, values, spacing } = grid;
  const gx = clamp(x / spacing, 0, width - 1);
  const gy = clamp(height - 1 - y / spacing, 0, height - 1);
  const x0 = Math.min(Math.floor(gx), width - 2);
  const y0 = Math.min(Math.floor(gy), height - 2);
  const fx = gx - x0;
  const fy = gy - y0;
  const at = (c: number, r: number) => values[r * width + c]!;
  const top = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx;
  const bottom = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx;
  return top * (1 - fy) + bottom * fy;
}

function clamp(v: number, lo: number, hi: number): number {
  return v < lo ? lo : v > hi ? hi : v;
}
