import { BufferAttribute, BufferGeometry, Color, Mesh, MeshStandardMaterial } from 'three';
import { hypsometric } from '../colormap.ts';
import { OUTSIDE_COLOR } from '../palette.ts';

/** The triangulated terrain as a flat-shaded mesh, vertex colours by elevation;
 * triangles outside the domain (group 1) in translucent grey. */
export function createSurface(): Mesh {
  const inside = new MeshStandardMaterial({
    vertexColors: true,
    flatShading: true, // every triangle shows: the triangulation is the point
    roughness: 0.92,
    metalness: 0,
    // Pushed back so that edges and overlays drawn on the same faces win.
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  const outside = new MeshStandardMaterial({
    color: OUTSIDE_COLOR,
    flatShading: true,
    roughness: 1,
    metalness: 0,
    transparent: true,
    opacity: 0.45,
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  return new Mesh(new BufferGeometry(), [inside, outside]);
}

/** Rebuilds the surface: world positions, heights (for colour) and triangles,
 * those inside the domain first (group 0), then those outside (group 1). */
export function updateSurface(surface: Mesh, positions: Float32Array, xyz: Float64Array, triangles: Uint32Array, inside: Uint8Array): void {
  const n = xyz.length / 3;
  let zmin = Infinity;
  let zmax = -Infinity;
  for (let i = 0; i < n; i++) {
    zmin = Math.min(zmin, xyz[3 * i + 2]!);
    zmax = Math.max(zmax, xyz[3 * i + 2]!);
  }
  const colors = new Float32Array(3 * n);
  const c = new Color();
  for (let i = 0; i < n; i++) {
    hypsometric((xyz[3 * i + 2]! - zmin) / (zmax - zmin || 1), c);
    colors.set([c.r, c.g, c.b], 3 * i);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setAttribute('color', new BufferAttribute(colors, 3));
  const index = new Uint32Array(triangles.length);
  let front = 0;
  let back = triangles.length;
  for (let k = 0; k < triangles.length / 3; k++) {
    const at = inside[k] === 0 ? (back -= 3) : (front += 3) - 3;
    index.set(triangles.subarray(3 * k, 3 * k + 3), at);
  }
  geometry.setIndex(new BufferAttribute(index, 1));
  geometry.addGroup(0, front, 0);
  geometry.addGroup(front, triangles.length - front, 1);
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  surface.geometry.dispose();
  surface.geometry = geometry;
}
