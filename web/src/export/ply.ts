// PLY, binary little endian: the points as doubles (exact), the triangles, and
// the attributes as uchar properties.
import { checkMesh, type MeshData, oneLine } from './meshData.js';

/**
 * Binary little endian PLY. Element `vertex`: `double x, y, z`, then, when given,
 * `uchar class` (the VertexClass: 0 convex, 1 concave, 2 flat, 3 mixed, 4 boundary,
 * 255 not a vertex) and `uchar extremum` (0 none, 1 local minimum, 2 local
 * maximum). Element `face`: `list uchar uint vertex_indices` (0-based,
 * counterclockwise seen from +z), then, when given, `uchar non_delaunay` (1 for a
 * triangle not in the Delaunay triangulation) and `uchar outside` (1 for a triangle
 * outside the domain). The header's comments say so too.
 */
export function toPLY(mesh: MeshData): Uint8Array {
  const { points: n, triangles: m } = checkMesh(mesh);
  const { points: p, triangles: t, vertexClass, extremum, nonDelaunay, outside } = mesh;
  const header = ['ply', 'format binary_little_endian 1.0'];
  if (mesh.comment) header.push(`comment ${oneLine(mesh.comment)}`);
  if (mesh.crs) header.push(`comment crs ${oneLine(mesh.crs)}`);
  if (vertexClass) header.push('comment class: 0 convex, 1 concave, 2 flat, 3 mixed, 4 boundary, 255 not a vertex');
  if (extremum) header.push('comment extremum: 0 none, 1 local minimum, 2 local maximum');
  if (nonDelaunay) header.push('comment non_delaunay: 1 if the triangle is not in the Delaunay triangulation');
  if (outside) header.push('comment outside: 1 if the triangle is outside the domain (an edge over maxEdge)');
  header.push(`element vertex ${n}`, 'property double x', 'property double y', 'property double z');
  if (vertexClass) header.push('property uchar class');
  if (extremum) header.push('property uchar extremum');
  header.push(`element face ${m}`, 'property list uchar uint vertex_indices');
  if (nonDelaunay) header.push('property uchar non_delaunay');
  if (outside) header.push('property uchar outside');
  header.push('end_header');
  const head = new TextEncoder().encode(`${header.join('\n')}\n`);

  const vertexSize = 24 + (vertexClass ? 1 : 0) + (extremum ? 1 : 0);
  const faceSize = 13 + (nonDelaunay ? 1 : 0) + (outside ? 1 : 0);
  const out = new Uint8Array(head.length + n * vertexSize + m * faceSize);
  out.set(head);
  const view = new DataView(out.buffer);
  let at = head.length;
  for (let i = 0; i < n; i++) {
    view.setFloat64(at, p[3 * i]!, true);
    view.setFloat64(at + 8, p[3 * i + 1]!, true);
    view.setFloat64(at + 16, p[3 * i + 2]!, true);
    at += 24;
    if (vertexClass) view.setUint8(at++, vertexClass[i]!);
    if (extremum) view.setUint8(at++, extremum[i]!);
  }
  for (let k = 0; k < m; k++) {
    view.setUint8(at, 3);
    view.setUint32(at + 1, t[3 * k]!, true);
    view.setUint32(at + 5, t[3 * k + 1]!, true);
    view.setUint32(at + 9, t[3 * k + 2]!, true);
    at += 13;
    if (nonDelaunay) view.setUint8(at++, nonDelaunay[k]!);
    if (outside) view.setUint8(at++, outside[k]!);
  }
  return out;
}
