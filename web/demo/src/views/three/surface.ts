import { BufferAttribute, BufferGeometry, Color, Mesh, MeshStandardMaterial } from 'three';
import { hypsometric } from '../colormap.ts';

/** The triangulated terrain as a flat-shaded mesh, vertex colours by elevation. */
export function createSurface(): Mesh {
  const material = new MeshStandardMaterial({
    vertexColors: true,
    flatShading: true, // every triangle shows: the triangulation is the point
    roughness: 0.92,
    metalness: 0,
    // Pushed back so that edges and overlays drawn on the same faces win.
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  return new Mesh(new BufferGeometry(), material);
}

/** Rebuilds the surface: world positions, heights (for colour) and triangles. */
export function updateSurface(surface: Mesh, positions: Float32Array, xyz: Float64Array, triangles: Uint32Array): void {
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
  geometry.setIndex(new BufferAttribute(triangles, 1));
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  surface.geometry.dispose();
  surface.geometry = geometry;
}
