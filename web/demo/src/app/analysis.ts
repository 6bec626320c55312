import type { Choice, ObjectiveValues, Terrain } from 'hodt';
import { nonDelaunayTriangles } from 'hodt/export';

/** Everything the views draw for one triangulation; every index is a point
 * index (the points as given to hodt.terrain). */
export interface Analysis {
  /** x, y, z per input point. */
  points: Float64Array;
  /** Input indices, three per triangle. */
  triangles: Uint32Array;
  halfedges: Int32Array;
  hull: Uint32Array;
  /** Per halfedge: 0 convex, 1 reflex, 2 flat, 3 hull. */
  edgeShape: Uint8Array;
  /** Per input point: 0 convex, 1 concave, 2 flat, 3 mixed, 4 boundary. */
  vertexClass: Uint8Array;
  /** Per input point: 0 none, 1 local minimum, 2 local maximum. */
  extremum: Uint8Array;
  degree: Uint32Array;
  /** Per triangle: 1 inside the domain (every triangle without one), 0 outside
   * (greyed, not measured). */
  inside: Uint8Array;
  /** a, b (Delaunay diagonal), c, d per flippable quad, input indices. */
  quads: Uint32Array;
  quadOfTriangle: Int32Array;
  choice: Choice;
  /** Higher order results (not a choice of quad diagonals): per triangle slot, 1
   * if the triangle is not a Delaunay triangle; null for first order. */
  changed: Uint8Array | null;
  /** Triangles (input indices) of the pair attaining a min-max value, if any. */
  critical: { first: Uint32Array; second: Uint32Array } | null;
  /** All 13 objective values of this triangulation and of Delaunay; null in a
   * live preview (dragging), where only the picture is updated. */
  values: ObjectiveValues | null;
  delaunayValues: ObjectiveValues | null;
}

/** The structure of a terrain that does not depend on the choice. */
export interface Structure {
  quads: Uint32Array;
  quadOfTriangle: Int32Array;
  delaunayValues: ObjectiveValues | null;
}

/** Without values (a live preview while dragging), delaunayValues is null. */
export function readStructure(terrain: Terrain, withValues = true): Structure {
  return {
    quads: terrain.quads,
    quadOfTriangle: terrain.quadOfTriangle,
    delaunayValues: withValues ? terrain.delaunayValues() : null,
  };
}

export function analyse(
  terrain: Terrain,
  structure: Structure,
  points: Float64Array,
  choice: Choice,
  critical: Analysis['critical'] = null,
): Analysis {
  const t = terrain.triangulation(choice);
  const m = terrain.measures(choice);
  return {
    points,
    triangles: t.triangles,
    halfedges: t.halfedges,
    hull: t.hull,
    edgeShape: m.edgeShape,
    vertexClass: m.vertexClass,
    extremum: m.extremum,
    degree: m.degree,
    inside: m.inside,
    quads: structure.quads,
    quadOfTriangle: structure.quadOfTriangle,
    choice,
    changed: null,
    critical,
    values: structure.delaunayValues ? terrain.evaluate(choice) : null,
    delaunayValues: structure.delaunayValues,
  };
}

/** Count of quads whose diagonal is not the Delaunay one. */
export function countFlipped(choice: Choice): number {
  let k = 0;
  for (const c of choice) k += c ? 1 : 0;
  return k;
}

/** The analysis of any triangulation of the terrain's points given as triangles
 * (an order-k result): its measures and values from the library, halfedges
 * matched here, and the triangles that are not Delaunay triangles marked. */
export function analyseTriangles(terrain: Terrain, structure: Structure, points: Float64Array, triangles: Uint32Array): Analysis {
  const delaunay = terrain.delaunay();
  const m = terrain.measuresOfTriangles(triangles);
  const numTriangles = triangles.length / 3;
  const changed = nonDelaunayTriangles(triangles, delaunay.triangles);
  return {
    points,
    triangles,
    halfedges: matchHalfedges(triangles),
    hull: delaunay.hull,
    edgeShape: m.edgeShape,
    vertexClass: m.vertexClass,
    extremum: m.extremum,
    degree: m.degree,
    inside: m.inside,
    quads: structure.quads,
    quadOfTriangle: new Int32Array(numTriangles).fill(-1),
    choice: new Uint8Array(0),
    changed,
    critical: null,
    values: structure.delaunayValues ? terrain.evaluateTriangles(triangles) : null,
    delaunayValues: structure.delaunayValues,
  };
}

/** Twin of each halfedge (e of triangle floor(e / 3), from triangles[e] to the
 * next corner), -1 on the hull. */
export function matchHalfedges(triangles: Uint32Array): Int32Array {
  const twin = new Int32Array(triangles.length).fill(-1);
  const open = new Map<number, number>();
  const n = 0x200000; // point indices are below 2^21 (the demo takes 20,000 points)
  for (let e = 0; e < triangles.length; e++) {
    const u = triangles[e]!;
    const v = triangles[e % 3 === 2 ? e - 2 : e + 1]!;
    const back = open.get(v * n + u);
    if (back !== undefined) {
      twin[e] = back;
      twin[back] = e;
      open.delete(v * n + u);
    } else open.set(u * n + v, e);
  }
  return twin;
}
