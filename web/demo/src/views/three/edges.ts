import { BufferAttribute, BufferGeometry, LineBasicMaterial, LineSegments } from 'three';
import type { Triangulation } from 'hodt';

/** Each edge of a triangulation once, as pairs of point indices. */
export function edgeIndex(t: Triangulation): Uint32Array {
  const { triangles, halfedges } = t;
  const out: number[] = [];
  for (let e = 0; e < triangles.length; e++) {
    const twin = halfedges[e]!;
    if (twin > e) continue; // the twin with the larger index draws it
    const next = e % 3 === 2 ? e - 2 : e + 1;
    out.push(triangles[e]!, triangles[next]!);
  }
  return Uint32Array.from(out);
}

/** Thin dark wireframe of the triangulation over the surface. */
export function createEdges(xyz: Float64Array, t: Triangulation): LineSegments {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(Float32Array.from(xyz), 3));
  geometry.setIndex(new BufferAttribute(edgeIndex(t), 1));
  const material = new LineBasicMaterial({ color: 0x1d2a24, transparent: true, opacity: 0.32 });
  return new LineSegments(geometry, material);
}

export function setEdgesTriangulation(edges: LineSegments, t: Triangulation): void {
  edges.geometry.setIndex(new BufferAttribute(edgeIndex(t), 1));
}
