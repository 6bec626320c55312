import { Group, Mesh, Raycaster, Vector2, Vector3, type Camera } from 'three';
import type { Analysis } from '../../app/analysis.ts';
import { createEdgeLines, updateEdgeLines } from './edgeLines.ts';
import { frameOfReference, worldPositions, type FrameOfReference } from './frameOfReference.ts';
import { createQuadFill, updateQuadFill } from './quadFill.ts';
import { createSurface, updateSurface } from './surface.ts';
import { createVertexMarkers } from './vertexMarkers.ts';

/** The terrain in the 3D view: surface, coloured edges, quads and vertex markers. */
export interface TerrainScene {
  readonly object: Group;
  /** Draws an analysis. With reframe, recomputes the centre and the height
   * exaggeration (a new terrain; `exaggeration`, if given, instead of the
   * automatic one); without, keeps them (an edit). */
  show(a: Analysis, reframe: boolean, exaggeration?: number | null): void;
  select(index: number | null): void;
  /** The points in world space, for framing the camera. */
  worldPoints(): Vector3[];
  /** World position of point i. */
  worldPoint(i: number): Vector3;
  /** The vertex nearest the surface point under ndc (normalised device
   * coordinates), or null if the ray misses the terrain. */
  pick(ndc: Vector2, camera: Camera): number | null;
  readonly frame: FrameOfReference | null;
}

export function createTerrainScene(): TerrainScene {
  const surface = createSurface();
  const edges = createEdgeLines();
  const fill = createQuadFill();
  const markers = createVertexMarkers();
  const object = new Group();
  object.add(surface, fill, edges, markers.object);

  let frame: FrameOfReference | null = null;
  let positions: Float32Array = new Float32Array(0);
  let current: Analysis | null = null;
  let selected: number | null = null;
  const raycaster = new Raycaster();

  return {
    object,
    get frame() {
      return frame;
    },
    show(a, reframe, exaggeration = null) {
      if (reframe || !frame) frame = frameOfReference(a.points, exaggeration);
      current = a;
      positions = worldPositions(a.points, frame);
      updateSurface(surface, positions, a.points, a.triangles, a.inside);
      updateEdgeLines(edges, positions, a);
      updateQuadFill(fill, positions, a);
      markers.update(positions, a, frame.extent * 0.011);
      markers.select(positions, selected);
    },
    select(index) {
      selected = index;
      markers.select(positions, index);
    },
    worldPoints() {
      const out: Vector3[] = [];
      for (let i = 0; i < positions.length; i += 3) out.push(new Vector3().fromArray(positions, i));
      return out;
    },
    worldPoint(i) {
      return new Vector3().fromArray(positions, 3 * i).applyMatrix4(object.matrixWorld);
    },
    pick(ndc, camera) {
      if (!current) return null;
      raycaster.setFromCamera(ndc, camera);
      const hit = raycaster.intersectObject(surface as Mesh, false)[0];
      if (!hit || hit.faceIndex == null) return null;
      const local = surface.worldToLocal(hit.point.clone());
      let best: number | null = null;
      let bestDistance = Infinity;
      for (let j = 0; j < 3; j++) {
        const v = current.triangles[3 * hit.faceIndex + j]!;
        const d = local.distanceToSquared(new Vector3().fromArray(positions, 3 * v));
        if (d < bestDistance) {
          bestDistance = d;
          best = v;
        }
      }
      return best;
    },
  };
}
