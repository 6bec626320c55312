// Wavefront OBJ: `v x y z` per point, `f i j k` per triangle (1-based).
import { checkMesh, type MeshData, oneLine } from './meshData.js';
import { TextParts } from './text.js';

/** The OBJ text in parts (see text.ts). */
export function objParts(mesh: MeshData): string[] {
  const { points: n, triangles: m } = checkMesh(mesh);
  const { points: p, triangles: t } = mesh;
  const out = new TextParts();
  if (mesh.comment) out.line(`# ${oneLine(mesh.comment)}`);
  out.line(`# ${n} vertices, ${m} triangles (counterclockwise seen from +z)`);
  // String(number) is the shortest decimal that reads back to the same double.
  for (let i = 0; i < 3 * n; i += 3) out.line(`v ${String(p[i])} ${String(p[i + 1])} ${String(p[i + 2])}`);
  for (let k = 0; k < 3 * m; k += 3) out.line(`f ${t[k]! + 1} ${t[k + 1]! + 1} ${t[k + 2]! + 1}`);
  return out.done();
}

/**
 * Wavefront OBJ text: a `v x y z` line per point (every coordinate the shortest
 * decimal that reads back to the same double) and an `f i j k` line per triangle
 * (1-based point indices, counterclockwise seen from +z). The comment and the
 * counts are `#` lines at the top. OBJ has no place for the attributes.
 */
export function toOBJ(mesh: MeshData): string {
  return objParts(mesh).join('');
}
