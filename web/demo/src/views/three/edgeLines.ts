import { Color } from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import type { Analysis } from '../../app/analysis.ts';
import { EDGE_SHAPE_COLORS } from '../palette.ts';

/** Every edge of the triangulation, coloured convex / reflex / flat / hull. */
export function createEdgeLines(): LineSegments2 {
  const material = new LineMaterial({ vertexColors: true, linewidth: 1.4, worldUnits: false });
  return new LineSegments2(new LineSegmentsGeometry(), material);
}

const SHAPE_COLORS = EDGE_SHAPE_COLORS.map((hex) => new Color(hex));

export function updateEdgeLines(lines: LineSegments2, positions: Float32Array, a: Analysis): void {
  const { triangles, halfedges, edgeShape } = a;
  const seg: number[] = [];
  const col: number[] = [];
  for (let e = 0; e < triangles.length; e++) {
    if (halfedges[e]! > e) continue; // draw each edge once
    const next = e % 3 === 2 ? e - 2 : e + 1;
    const u = triangles[e]!;
    const v = triangles[next]!;
    seg.push(positions[3 * u]!, positions[3 * u + 1]!, positions[3 * u + 2]!);
    seg.push(positions[3 * v]!, positions[3 * v + 1]!, positions[3 * v + 2]!);
    const c = SHAPE_COLORS[edgeShape[e]!] ?? SHAPE_COLORS[2]!;
    col.push(c.r, c.g, c.b, c.r, c.g, c.b);
  }
  const geometry = new LineSegmentsGeometry();
  geometry.setPositions(seg);
  geometry.setColors(col);
  lines.geometry.dispose();
  lines.geometry = geometry;
}
