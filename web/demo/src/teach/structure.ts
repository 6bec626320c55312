import type { Terrain } from 'hodt';

/** The first order structure of a terrain as the teaching views draw it, read
 * from the library: the triangles of every quad in both states, which quads
 * share an edge, where each quad is. Everything is a point index. The views
 * compute nothing from it: what the solvers decided comes from terrain.explain. */
export interface QuadStructure {
  points: Float64Array;
  /** Number of flippable quads m. */
  m: number;
  /** a, b (Delaunay diagonal), c, d per quad. */
  quads: Uint32Array;
  /** Triangles of the all-Delaunay choice [0] and the all-flipped choice [1]:
   * same slots, so a quad's two slots hold its two triangles in either state. */
  tri: [Uint32Array, Uint32Array];
  /** Per triangle slot: its quad or -1 (fixed). */
  slotQuad: Int32Array;
  /** Two slots per quad. */
  quadSlots: Int32Array;
  /** Pairs of quads sharing an edge (q < r), each once. */
  quadEdges: [number, number][];
  /** Plane position of each quad's centre (mean of its corners). */
  centroid: Float64Array;
}

export function readStructure(terrain: Terrain): QuadStructure {
  const points = terrain.points;
  const quads = terrain.quads;
  const m = quads.length / 4;
  const t0 = terrain.triangulation(new Uint8Array(m));
  const t1 = terrain.triangulation(new Uint8Array(m).fill(1));
  const slotQuad = terrain.quadOfTriangle;
  const quadSlots = new Int32Array(2 * m).fill(-1);
  for (let k = 0; k < slotQuad.length; k++) {
    const q = slotQuad[k]!;
    if (q < 0) continue;
    if (quadSlots[2 * q]! < 0) quadSlots[2 * q] = k;
    else quadSlots[2 * q + 1] = k;
  }
  // Quads whose triangles meet across a Delaunay edge.
  const seen = new Set<number>();
  const quadEdges: [number, number][] = [];
  const he = t0.halfedges;
  for (let e = 0; e < he.length; e++) {
    const f = he[e]!;
    if (f < e) continue;
    const a = slotQuad[Math.floor(e / 3)]!, b = slotQuad[Math.floor(f / 3)]!;
    if (a < 0 || b < 0 || a === b) continue;
    const q = Math.min(a, b), r = Math.max(a, b);
    if (!seen.has(q * 0x100000 + r)) {
      seen.add(q * 0x100000 + r);
      quadEdges.push([q, r]);
    }
  }
  const centroid = new Float64Array(2 * m);
  for (let q = 0; q < m; q++) {
    for (let j = 0; j < 4; j++) {
      const p = quads[4 * q + j]!;
      centroid[2 * q]! += points[3 * p]! / 4;
      centroid[2 * q + 1]! += points[3 * p + 1]! / 4;
    }
  }
  return { points, m, quads, tri: [t0.triangles, t1.triangles], slotQuad, quadSlots, quadEdges, centroid };
}

/** Triangles (point indices) of a choice, from the two precomputed states. */
export function trianglesOf(s: QuadStructure, choice: ArrayLike<number>): Uint32Array {
  const out = s.tri[0].slice();
  for (let k = 0; k < s.slotQuad.length; k++) {
    const q = s.slotQuad[k]!;
    if (q >= 0 && choice[q]) out.set(s.tri[1].subarray(3 * k, 3 * k + 3), 3 * k);
  }
  return out;
}
