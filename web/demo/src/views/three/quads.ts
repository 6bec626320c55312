import { BufferAttribute, BufferGeometry, Color, DoubleSide, Group, Mesh, MeshBasicMaterial } from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import type { Choice, Triangulation } from 'hodt';

/** Quad colours: on their Delaunay diagonal, and flipped to the other one. */
export const QUAD_COLOR = '#d6248f';
export const FLIPPED_COLOR = '#1f7fe0';

/** Highlight of the flippable quads: their two triangles filled translucent and
 * their current diagonal drawn bold. */
export interface QuadOverlay {
  readonly object: Group;
  /** Redraws for a triangulation and the choice it came from (all zeros: Delaunay). */
  update(t: Triangulation, choice: Choice): void;
}

export function createQuadOverlay(
  xyz: Float64Array,
  quads: Uint32Array,
  quadOfTriangle: Int32Array,
): QuadOverlay {
  const base = new Color(QUAD_COLOR);
  const flipped = new Color(FLIPPED_COLOR);

  const fill = new Mesh(
    new BufferGeometry(),
    new MeshBasicMaterial({
      vertexColors: true,
      transparent: true,
      opacity: 0.2,
      depthWrite: false,
      side: DoubleSide,
    }),
  );
  const diagonals = new LineSegments2(
    new LineSegmentsGeometry(),
    new LineMaterial({ vertexColors: true, linewidth: 2, worldUnits: false }),
  );
  const object = new Group();
  object.add(fill, diagonals);

  const update = (t: Triangulation, choice: Choice) => {
    const pos: number[] = [];
    const col: number[] = [];
    for (let k = 0; k < quadOfTriangle.length; k++) {
      const q = quadOfTriangle[k]!;
      if (q < 0) continue;
      const c = choice[q] ? flipped : base;
      for (let j = 0; j < 3; j++) {
        const v = t.triangles[3 * k + j]!;
        pos.push(xyz[3 * v]!, xyz[3 * v + 1]!, xyz[3 * v + 2]!);
        col.push(c.r, c.g, c.b);
      }
    }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(Float32Array.from(pos), 3));
    geometry.setAttribute('color', new BufferAttribute(Float32Array.from(col), 3));
    fill.geometry.dispose();
    fill.geometry = geometry;

    const m = quads.length / 4;
    const seg = new Float32Array(m * 6);
    const segCol = new Float32Array(m * 6);
    for (let q = 0; q < m; q++) {
      const on = choice[q] ? 1 : 0;
      const u = quads[4 * q + 2 * on]!; // a, b or c, d
      const w = quads[4 * q + 2 * on + 1]!;
      seg.set([xyz[3 * u]!, xyz[3 * u + 1]!, xyz[3 * u + 2]!, xyz[3 * w]!, xyz[3 * w + 1]!, xyz[3 * w + 2]!], 6 * q);
      const c = (on ? flipped : base).clone().multiplyScalar(0.55);
      segCol.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * q);
    }
    const lines = new LineSegmentsGeometry();
    lines.setPositions(seg);
    lines.setColors(segCol);
    diagonals.geometry.dispose();
    diagonals.geometry = lines;
  };

  return { object, update };
}
