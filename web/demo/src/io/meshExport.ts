import { exportMesh, MESH_FORMATS, type MeshFormat } from 'hodt/export';
import type { Analysis } from '../app/analysis.ts';

/** Per triangle slot of a first order triangulation: 1 if its quad is flipped. */
function flippedTriangles(a: Analysis): Uint8Array {
  return Uint8Array.from(a.quadOfTriangle, (q) => (q >= 0 && a.choice[q] ? 1 : 0));
}

/** The shown triangulation as a file of the library's writers (hodt/export), with
 * the vertex classes, extrema and non-Delaunay triangles the views show, and
 * within a domain which triangles are outside. */
export function meshFile(format: MeshFormat, shown: Analysis, comment: string, domain: boolean): { bytes: Uint8Array; type: string } {
  const bytes = exportMesh(format, {
    points: shown.points,
    triangles: shown.triangles,
    vertexClass: shown.vertexClass,
    extremum: shown.extremum,
    nonDelaunay: shown.changed ?? flippedTriangles(shown),
    ...(domain ? { outside: shown.inside.map((v) => 1 - v) } : {}),
    comment,
  });
  return { bytes, type: MESH_FORMATS[format].mediaType };
}
