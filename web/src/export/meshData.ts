// What every writer of hodt/export takes, and the checks they share.
import { InputError } from '../errors.js';

/** The file formats of hodt/export. */
export type MeshFormat = 'obj' | 'ply' | 'geojson' | 'glb';

/** A triangulation of points with its attributes: what the writers take. */
export interface MeshData {
  /** x, y, z per point (for example `terrain.points`). Text formats write each
   * number as the shortest decimal that reads back to the same double; PLY writes
   * doubles; glTF float32 offsets (see toGLB). */
  points: ArrayLike<number>;
  /** Three point indices per triangle, counterclockwise seen from +z (for
   * example `solution.triangles`). Points no triangle uses are written too. */
  triangles: ArrayLike<number>;
  /** Per point: a `VertexClass` value (PLY property `class`). */
  vertexClass?: ArrayLike<number>;
  /** Per point: an `Extremum` value (PLY property `extremum`). */
  extremum?: ArrayLike<number>;
  /** Per triangle: 1 if it is not a triangle of the Delaunay triangulation, else 0
   * (PLY property `non_delaunay`, GeoJSON property `delaunay`); see
   * nonDelaunayTriangles. */
  nonDelaunay?: ArrayLike<number>;
  /** Per triangle: 1 if it is outside the terrain's domain (Terrain.maxEdge),
   * else 0 (PLY property `outside`, GeoJSON property `inside`); see
   * Measures.inside. */
  outside?: ArrayLike<number>;
  /** One line about the triangulation, written as a comment (OBJ, PLY) or in the
   * glTF asset's `extras`. */
  comment?: string;
  /** The coordinate reference system as an EPSG code ("EPSG:32633"), written as
   * GeoJSON's named `crs` member (read by GDAL and QGIS), a `crs` comment (OBJ,
   * PLY) and the glTF asset's `extras.crs`. */
  crs?: string;
}

/** Checks the mesh (throws InputError naming what is wrong); its counts. */
export function checkMesh(mesh: MeshData): { points: number; triangles: number } {
  const { points, triangles } = mesh;
  if (!points || typeof points.length !== 'number' || points.length % 3 !== 0) {
    throw new InputError(`points has ${String(points?.length)} numbers, expected x, y, z per point (a multiple of 3)`);
  }
  if (!triangles || typeof triangles.length !== 'number' || triangles.length % 3 !== 0) {
    throw new InputError(`triangles has ${String(triangles?.length)} indices, expected three per triangle (a multiple of 3)`);
  }
  const n = points.length / 3, m = triangles.length / 3;
  for (let i = 0; i < points.length; i++) {
    const v = points[i]!;
    if (typeof v !== 'number' || !Number.isFinite(v)) {
      throw new InputError(`point ${Math.floor(i / 3)}: ${'xyz'[i % 3]} is ${String(v)}, expected a finite number`);
    }
  }
  for (let k = 0; k < triangles.length; k++) {
    const v = triangles[k]!;
    if (!Number.isInteger(v) || v < 0 || v >= n) {
      throw new InputError(`triangle ${Math.floor(k / 3)}: point index ${String(v)} is not a point (there are ${n})`);
    }
  }
  checkBytes('vertexClass', mesh.vertexClass, n, 'point');
  checkBytes('extremum', mesh.extremum, n, 'point');
  checkBytes('nonDelaunay', mesh.nonDelaunay, m, 'triangle');
  checkBytes('outside', mesh.outside, m, 'triangle');
  return { points: n, triangles: m };
}

function checkBytes(name: string, values: ArrayLike<number> | undefined, count: number, per: string): void {
  if (values === undefined) return;
  if (values.length !== count) throw new InputError(`${name} has ${values.length} values, expected one per ${per} (${count})`);
  for (let i = 0; i < count; i++) {
    const v = values[i]!;
    if (!Number.isInteger(v) || v < 0 || v > 255) throw new InputError(`${name}[${i}] is ${String(v)}, expected an integer from 0 to 255`);
  }
}

/** A comment on one line (formats end comments at the line's end). */
export function oneLine(text: string): string {
  return text.replace(/[\r\n]+/g, ' ');
}
