/**
 * hodt/three: a terrain triangulation as a three.js BufferGeometry.
 *
 *   import * as THREE from 'three';
 *   import { terrainGeometry, setTriangles } from 'hodt/three';
 *   const geometry = terrainGeometry(THREE, terrain.points, terrain.delaunay().triangles);
 *   setTriangles(geometry, terrain.solve('min-local-minima').triangles);
 *
 * This module never imports three at run time: you pass your THREE (or an object
 * with its BufferGeometry and BufferAttribute classes), so the core entry point
 * and this one work with any three from 0.150. Only its types come from three
 * (with TypeScript, have @types/three installed).
 */
import type * as Three from 'three';
import { InputError } from './errors.js';

/** The classes hodt needs from three: pass `THREE` itself (`import * as THREE from 'three'`). */
export type ThreeClasses = Pick<typeof Three, 'BufferGeometry' | 'BufferAttribute'>;

export interface GeometryOptions {
  /** Which three.js axis the terrain's heights (z) go to. 'z' (default) keeps x, y,
   * z as they are (set `camera.up.set(0, 0, 1)`); 'y' maps (x, y, z) to (x, z, -y),
   * a rotation, so the surface faces +y as three's default camera expects. */
  up?: 'z' | 'y';
  /** Subtracted from every point before the conversion to 32-bit floats: give the
   * terrain's centre when coordinates are large (UTM metres lose about 6 cm at
   * 10^6 in Float32). Default [0, 0, 0]. */
  origin?: readonly [number, number, number];
}

/**
 * A new BufferGeometry: a `position` attribute from the points (x, y, z per
 * point, as given to hodt.terrain()), the triangles as its index, and vertex
 * normals. The geometry is yours (three's `geometry.dispose()` frees its GPU
 * buffers); it does not refer to the terrain.
 */
export function terrainGeometry(
  THREE: ThreeClasses,
  points: ArrayLike<number>,
  triangles: Uint32Array,
  options: GeometryOptions = {},
): Three.BufferGeometry {
  const { up = 'z', origin = [0, 0, 0] } = options;
  const [ox, oy, oz] = origin;
  const n = Math.floor(points.length / 3);
  const position = new Float32Array(3 * n);
  for (let i = 0; i < n; ++i) {
    const x = points[3 * i]! - ox, y = points[3 * i + 1]! - oy, z = points[3 * i + 2]! - oz;
    position[3 * i] = x;
    if (up === 'y') {
      position[3 * i + 1] = z;
      position[3 * i + 2] = -y;
    } else {
      position[3 * i + 1] = y;
      position[3 * i + 2] = z;
    }
  }
  for (const v of triangles) {
    if (v >= n) throw new InputError(`triangles refer to point ${v}, but there are ${n} points`);
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
  geometry.setIndex(new THREE.BufferAttribute(Uint32Array.from(triangles), 1));
  geometry.computeVertexNormals();
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  return geometry;
}

/**
 * Shows another triangulation of the same points (for example a Solution's
 * `triangles`) in a geometry made by terrainGeometry(): copies the triangles into
 * its index in place (every first order triangulation of a terrain has the same
 * number of triangles), marks it for upload and recomputes the normals.
 */
export function setTriangles(geometry: Three.BufferGeometry, triangles: Uint32Array): void {
  const index = geometry.getIndex();
  if (!index) throw new InputError('the geometry has no index: make it with terrainGeometry()');
  if (index.array.length !== triangles.length) {
    throw new InputError(
      `the geometry's index has ${index.array.length} entries, the triangles ${triangles.length}: ` +
        'not a triangulation of the same terrain; make a new geometry with terrainGeometry()',
    );
  }
  index.array.set(triangles);
  index.needsUpdate = true;
  geometry.computeVertexNormals();
}
