import { Group, Vector3 } from 'three';
import type { Choice, Triangulation } from 'hodt';
import { createEdges, setEdgesTriangulation } from './edges.ts';
import { createQuadOverlay } from './quads.ts';
import { createSurface, setSurfaceTriangles } from './surface.ts';

/** Surface, wireframe and flippable quads of one terrain, in data coordinates,
 * centred on the origin with the heights exaggerated. */
export interface TerrainView {
  readonly object: Group;
  /** The points in world space, for framing the camera. */
  readonly worldPoints: Vector3[];
  show(t: Triangulation, choice: Choice): void;
}

export function createTerrainView(
  xyz: Float64Array,
  quads: Uint32Array,
  quadOfTriangle: Int32Array,
  delaunay: Triangulation,
  exaggeration = 1.8,
): TerrainView {
  const surface = createSurface(xyz, delaunay.triangles);
  const edges = createEdges(xyz, delaunay);
  const overlay = createQuadOverlay(xyz, quads, quadOfTriangle);
  overlay.update(delaunay, new Uint8Array(quads.length / 4));

  const object = new Group();
  object.add(surface, edges, overlay.object);
  const box = surface.geometry.boundingBox!;
  const center = box.getCenter(new Vector3());
  object.scale.set(1, 1, exaggeration);
  object.position.set(-center.x, -center.y, -box.min.z * exaggeration);
  object.updateMatrixWorld(true);
  const worldPoints: Vector3[] = [];
  for (let i = 0; i < xyz.length; i += 3) {
    worldPoints.push(new Vector3(xyz[i], xyz[i + 1], xyz[i + 2]).applyMatrix4(object.matrixWorld));
  }

  const show = (t: Triangulation, choice: Choice) => {
    setSurfaceTriangles(surface, t.triangles);
    setEdgesTriangulation(edges, t);
    overlay.update(t, choice);
  };
  return { object, worldPoints, show };
}
