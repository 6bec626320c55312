// Wavefront OBJ: `v x y z` per point, `f i j k` per triangle (1-based).
import { checkMesh, type MeshData, oneLine } from './meshData.js';
import { LineBatch } from './text.js';

/** The OBJ text in parts (see text.ts); the mesh is checked at once. */
export function objParts(mesh: MeshData): Iterable<string> {
  const counts = checkMesh(mesh);
  return objText(mesh, counts.points, counts.triangles);
}

function* objText(mesh: MeshData, n: number, m: number): Generator<string> {
  const { points: p, triangles: t } = mesh;
  const out = new LineBatch();
  if (mesh.comment) out.add(`# ${oneLine(mesh.comment)}`);
  if (mesh.crs) out.add(`# crs ${oneLine(mesh.crs)}`);
  out.add(`# ${n} vertices, ${m} triangles (counterclockwise seen from +z)`);
  // String(number) is the shortest decimal that reads back to the same double.
  for (let i = 0; i < 3 * n; i += 3) {
    if (out.add(`v ${String(p[i])} ${String(p[i + 1])} ${String(p[i + 2])}`)) yield out.take();
  }
  for (let k = 0; k < 3 * m; k += 3) {
    if (out.add(`f ${t[k]! + 1} ${t[k + 1]! + 1} ${t[k + 2]! + 1}`)) yield out.take();
  }
  yield out.take();
}

/**
 * Wavefront OBJ text: a `v x y z` line per point (every coordinate the shortest
 * decimal that reads back to the same double) and an `f i j k` line per triangle
 * (1-based point indices, counterclockwise seen from +z). The comment and the
 * counts are `#` lines at the top. OBJ has no place for the attributes.
 */
export function toOBJ(mesh: MeshData): string {
  return Array.from(objParts(mesh)).join('');
}
