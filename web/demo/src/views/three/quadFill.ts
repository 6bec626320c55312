import { BufferAttribute, BufferGeometry, Color, DoubleSide, Mesh, MeshBasicMaterial } from 'three';
import type { Analysis } from '../../app/analysis.ts';
import { criticalTriangles } from '../../app/criticalTriangles.ts';
import { CRITICAL_COLOR, FLIPPED_COLOR, QUAD_COLOR } from '../palette.ts';

/** Translucent fill of the flippable quads (teal, faint), the flipped ones (amber)
 * and the critical pair of a min-max objective (pink), drawn on the surface.
 * Alpha is per vertex, so the elevation colours still show through. */
export function createQuadFill(): Mesh {
  const material = new MeshBasicMaterial({
    vertexColors: true, // RGBA: alpha per vertex
    transparent: true,
    opacity: 1,
    depthWrite: false,
    side: DoubleSide,
  });
  return new Mesh(new BufferGeometry(), material);
}

const BASE = new Color(QUAD_COLOR);
const FLIPPED = new Color(FLIPPED_COLOR);
const CRITICAL = new Color(CRITICAL_COLOR);

export function updateQuadFill(fill: Mesh, positions: Float32Array, a: Analysis): void {
  const pos: number[] = [];
  const col: number[] = [];
  const push = (k: number, c: Color, alpha: number) => {
    for (let j = 0; j < 3; j++) {
      const v = a.triangles[3 * k + j]!;
      pos.push(positions[3 * v]!, positions[3 * v + 1]!, positions[3 * v + 2]!);
      col.push(c.r, c.g, c.b, alpha);
    }
  };
  const numTriangles = a.triangles.length / 3;
  for (let k = 0; k < numTriangles; k++) {
    const q = a.quadOfTriangle[k]!;
    if (q >= 0) push(k, a.choice[q] ? FLIPPED : BASE, a.choice[q] ? 0.62 : 0.28);
    else if (a.changed?.[k]) push(k, FLIPPED, 0.62); // a higher order result's non-Delaunay triangle
  }
  for (const k of criticalTriangles(a)) push(k, CRITICAL, 0.75);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(Float32Array.from(pos), 3));
  geometry.setAttribute('color', new BufferAttribute(Float32Array.from(col), 4));
  fill.geometry.dispose();
  fill.geometry = geometry;
}
