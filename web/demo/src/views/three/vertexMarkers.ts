import {
  BufferAttribute,
  BufferGeometry,
  Color,
  ConeGeometry,
  Group,
  InstancedMesh,
  Matrix4,
  MeshStandardMaterial,
  Points,
  PointsMaterial,
  Quaternion,
  Vector3,
} from 'three';
import type { Analysis } from '../../app/analysis.ts';
import { dotTexture } from '../dotTexture.ts';
import { EXTREMUM_COLORS, SELECTION_COLOR, VERTEX_CLASS_COLORS } from '../palette.ts';

/** Vertices as dots coloured by class, cones on local minima (pointing down) and
 * maxima (pointing up), and a ring around the selected point. */
export interface VertexMarkers {
  readonly object: Group;
  /** Rebuilds for an analysis; `size` is a length in world units for the cones. */
  update(positions: Float32Array, a: Analysis, size: number): void;
  select(positions: Float32Array, index: number | null): void;
}

const CLASS_COLORS = VERTEX_CLASS_COLORS.map((hex) => new Color(hex));
const MAX_CONES = 4096;

export function createVertexMarkers(): VertexMarkers {
  const dots = new Points(
    new BufferGeometry(),
    new PointsMaterial({ size: 7, sizeAttenuation: false, vertexColors: true, map: dotTexture(), alphaTest: 0.5 }),
  );
  const selection = new Points(
    new BufferGeometry(),
    new PointsMaterial({ size: 22, sizeAttenuation: false, color: SELECTION_COLOR, map: dotTexture(true), alphaTest: 0.5, depthTest: false }),
  );
  selection.renderOrder = 10;
  const cone = new ConeGeometry(0.5, 1, 14);
  const minima = new InstancedMesh(cone, new MeshStandardMaterial({ color: EXTREMUM_COLORS.minimum, roughness: 0.6 }), MAX_CONES);
  const maxima = new InstancedMesh(cone, new MeshStandardMaterial({ color: EXTREMUM_COLORS.maximum, roughness: 0.6 }), MAX_CONES);
  const object = new Group();
  object.add(dots, minima, maxima, selection);

  const m = new Matrix4();
  // ConeGeometry points along +y: turn it to -z (down) or +z (up).
  const down = new Quaternion().setFromAxisAngle(new Vector3(1, 0, 0), -Math.PI / 2);
  const up = new Quaternion().setFromAxisAngle(new Vector3(1, 0, 0), Math.PI / 2);
  const p = new Vector3();

  return {
    object,
    update(positions, a, size) {
      const n = positions.length / 3;
      const colors = new Float32Array(3 * n);
      for (let i = 0; i < n; i++) {
        const c = CLASS_COLORS[a.vertexClass[i]!] ?? CLASS_COLORS[4]!;
        colors.set([c.r, c.g, c.b], 3 * i);
      }
      const geometry = new BufferGeometry();
      geometry.setAttribute('position', new BufferAttribute(positions, 3));
      geometry.setAttribute('color', new BufferAttribute(colors, 3));
      dots.geometry.dispose();
      dots.geometry = geometry;

      // Cones (height 1.6 size) centred 0.8 size above the vertex: a minimum's tip
      // points down into the pit, a maximum's up from the peak.
      let lo = 0;
      let hi = 0;
      const scale = new Vector3(size, size * 1.6, size);
      for (let i = 0; i < n; i++) {
        const kind = a.extremum[i];
        if (!kind) continue;
        p.fromArray(positions, 3 * i);
        p.z += size * 0.8;
        if (kind === 1 && lo < MAX_CONES) minima.setMatrixAt(lo++, m.compose(p, down, scale));
        else if (kind === 2 && hi < MAX_CONES) maxima.setMatrixAt(hi++, m.compose(p, up, scale));
      }
      minima.count = lo;
      maxima.count = hi;
      minima.instanceMatrix.needsUpdate = true;
      maxima.instanceMatrix.needsUpdate = true;
      minima.computeBoundingSphere();
      maxima.computeBoundingSphere();
    },
    select(positions, index) {
      const geometry = new BufferGeometry();
      if (index !== null && 3 * index < positions.length) {
        geometry.setAttribute('position', new BufferAttribute(positions.slice(3 * index, 3 * index + 3), 3));
      } else {
        geometry.setAttribute('position', new BufferAttribute(new Float32Array(0), 3));
      }
      selection.geometry.dispose();
      selection.geometry = geometry;
    },
  };
}
