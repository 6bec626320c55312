import type { Terrain } from 'hodt';

/** The first order structure of a terrain as the teaching views need it: the
 * triangles of every quad in both states, the fixed edges between quads and
 * fixed triangles (the paper's subdivision S, Section 2.1), the quad graph and
 * the peeling depth of every quad (Section 4). Everything is a point index. */
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
  /** Delaunay halfedges and hull. */
  halfedges: Int32Array;
  hull: Uint32Array;
  /** Interior edges of the Delaunay triangulation that are not quad diagonals. */
  skeleton: SkeletonEdge[];
  /** Pairs of quads sharing a skeleton edge (q < r), each once. */
  quadEdges: [number, number][];
  /** Plane position of each quad's centre (mean of its corners). */
  centroid: Float64Array;
  /** Per point: Delaunay edges from the hull (BFS), per quad: the smallest over
   * its corners (the layer of Section 4). */
  pointDepth: Int32Array;
  quadDepth: Int32Array;
}

export interface Side {
  /** The quad on this side, or -1 for a fixed triangle. */
  quad: number;
  /** The triangle on this side in state 0 and in state 1 (the same if fixed). */
  tri: [Tri, Tri];
}
export type Tri = [number, number, number];

export interface SkeletonEdge {
  u: number;
  v: number;
  left: Side;
  right: Side;
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
  const tri: [Uint32Array, Uint32Array] = [t0.triangles, t1.triangles];
  const slotTri = (x: number, k: number): Tri => [tri[x]![3 * k]!, tri[x]![3 * k + 1]!, tri[x]![3 * k + 2]!];
  const side = (slot: number, u: number, v: number): Side => {
    const q = slotQuad[slot]!;
    if (q < 0) {
      const t = slotTri(0, slot);
      return { quad: -1, tri: [t, t] };
    }
    const pick = (x: number): Tri => {
      for (const k of [quadSlots[2 * q]!, quadSlots[2 * q + 1]!]) {
        const t = slotTri(x, k);
        if (t.includes(u) && t.includes(v)) return t;
      }
      throw new Error(`quad ${q} has no triangle on edge ${u}-${v}`);
    };
    return { quad: q, tri: [pick(0), pick(1)] };
  };

  const key = (u: number, v: number) => (u < v ? u * 0x100000 + v : v * 0x100000 + u);
  const diagonal = new Set<number>();
  for (let q = 0; q < m; q++) diagonal.add(key(quads[4 * q]!, quads[4 * q + 1]!));
  const skeleton: SkeletonEdge[] = [];
  const pairs = new Set<number>();
  const quadEdges: [number, number][] = [];
  const he = t0.halfedges;
  const tris = t0.triangles;
  for (let e = 0; e < he.length; e++) {
    const f = he[e]!;
    if (f < e) continue; // hull (-1) or seen from the twin
    const u = tris[e]!;
    const v = tris[e % 3 === 2 ? e - 2 : e + 1]!;
    if (diagonal.has(key(u, v))) continue;
    const left = side(Math.floor(e / 3), u, v);
    const right = side(Math.floor(f / 3), u, v);
    skeleton.push({ u, v, left, right });
    if (left.quad >= 0 && right.quad >= 0) {
      const q = Math.min(left.quad, right.quad);
      const r = Math.max(left.quad, right.quad);
      if (!pairs.has(q * 0x100000 + r)) {
        pairs.add(q * 0x100000 + r);
        quadEdges.push([q, r]);
      }
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

  // Peeling depth: BFS in the Delaunay graph from the hull.
  const n = points.length / 3;
  const adjacency: number[][] = Array.from({ length: n }, () => []);
  for (let e = 0; e < he.length; e++) {
    const u = tris[e]!;
    const v = tris[e % 3 === 2 ? e - 2 : e + 1]!;
    adjacency[u]!.push(v);
    if (he[e]! < 0) adjacency[v]!.push(u);
  }
  const pointDepth = new Int32Array(n).fill(-1);
  const queue: number[] = [];
  for (const v of t0.hull) {
    pointDepth[v] = 0;
    queue.push(v);
  }
  for (let i = 0; i < queue.length; i++) {
    const v = queue[i]!;
    for (const w of adjacency[v]!) {
      if (pointDepth[w]! < 0) {
        pointDepth[w] = pointDepth[v]! + 1;
        queue.push(w);
      }
    }
  }
  const quadDepth = new Int32Array(m);
  for (let q = 0; q < m; q++) {
    let d = Infinity;
    for (let j = 0; j < 4; j++) d = Math.min(d, pointDepth[quads[4 * q + j]!]!);
    quadDepth[q] = d;
  }

  return { points, m, quads, tri, slotQuad, quadSlots, halfedges: he, hull: t0.hull, skeleton, quadEdges, centroid, pointDepth, quadDepth };
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
