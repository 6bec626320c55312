// Which triangles of a triangulation are not Delaunay triangles: the per-triangle
// flag the writers take as MeshData.nonDelaunay.

/**
 * Per triangle of `triangles`: 1 if it is not a triangle of `delaunay` (for
 * example `terrain.delaunay().triangles`), else 0. Both are three point indices
 * per counterclockwise triangle; the corners may start anywhere.
 */
export function nonDelaunayTriangles(triangles: ArrayLike<number>, delaunay: ArrayLike<number>): Uint8Array {
  let n = 1;
  for (let i = 0; i < delaunay.length; i++) n = Math.max(n, delaunay[i]! + 1);
  for (let i = 0; i < triangles.length; i++) n = Math.max(n, triangles[i]! + 1);
  // A counterclockwise triangle started at its smallest corner a is known by its
  // directed edge (a, b): in one triangulation, one triangle has it.
  const start = (t: ArrayLike<number>, k: number): [number, number, number] => {
    const a = t[k]!, b = t[k + 1]!, c = t[k + 2]!;
    return a < b ? (a < c ? [a, b, c] : [c, a, b]) : b < c ? [b, c, a] : [c, a, b];
  };
  const apex = new Map<number, number>();
  for (let k = 0; k + 2 < delaunay.length; k += 3) {
    const [a, b, c] = start(delaunay, k);
    apex.set(a * n + b, c);
  }
  const out = new Uint8Array(Math.floor(triangles.length / 3));
  for (let k = 0; k < out.length; k++) {
    const [a, b, c] = start(triangles, 3 * k);
    out[k] = apex.get(a * n + b) === c ? 0 : 1;
  }
  return out;
}
