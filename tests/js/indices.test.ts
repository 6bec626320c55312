// Every index the API returns refers to the points as given, whatever the
// terrain's internal (spatial) vertex order.
import { beforeAll, describe, expect, it } from 'vitest';
import { EdgeShape, type Hodt, loadHodt, VertexClass } from '../../web/src/index.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

// A bump: a square grid whose centre point is the only local maximum.
function bump(side: number): Float64Array {
  const xyz: number[] = [];
  const c = (side - 1) / 2;
  for (let j = 0; j < side; ++j)
    for (let i = 0; i < side; ++i) xyz.push(i + 0.01 * Math.sin(7 * i + 3 * j), j + 0.01 * Math.cos(5 * i - j), -((i - c) ** 2 + (j - c) ** 2));
  return Float64Array.from(xyz);
}

describe('point indices', () => {
  it('points are the input, copied in; read as one cached array', () => {
    const xyz = bump(5);
    const x0 = xyz[0];
    using t = hodt.terrain(xyz);
    const p = t.points;
    expect(Array.from(p)).toEqual(Array.from(xyz));
    xyz[0] = 99;  // the terrain kept its own copy
    expect(t.points[0]).toBe(x0);
    expect(t.points).toBe(p);  // (the same array until the terrain changes: docs/api.md)
    expect(t.numInputPoints).toBe(25);
  });

  it('per-point measures are indexed like the triangles', () => {
    const side = 7;
    const xyz = bump(side);
    using t = hodt.terrain(xyz);
    const m = t.measures();
    const centre = (side * side - 1) / 2;
    expect(m.vertexClass.length).toBe(side * side);
    expect(m.extremum[centre]).toBe(2); // the only maximum
    expect(m.extremum.filter((e) => e === 2).length).toBe(1);
    // Degrees agree with the triangles.
    const { triangles, halfedges } = t.delaunay();
    const neighbours = Array.from({ length: side * side }, () => new Set<number>());
    for (let k = 0; k < triangles.length; ++k) {
      const a = triangles[k]!, b = triangles[k - (k % 3) + ((k + 1) % 3)]!;
      neighbours[a]!.add(b);
      neighbours[b]!.add(a);
    }
    expect(Array.from(m.degree)).toEqual(neighbours.map((s) => s.size));
    // Corners are on the hull.
    expect(m.vertexClass[0]).toBe(VertexClass.Boundary);
    expect(m.edgeShape.length).toBe(halfedges.length);
    for (let e = 0; e < halfedges.length; ++e) if (halfedges[e] === -1) expect(m.edgeShape[e]).toBe(EdgeShape.Hull);
  });

  it('dropped duplicates are marked, and vertexIndex lists the kept points', () => {
    const xyz = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 9, 1, 1, 1, 0.5, 0.4, 2];
    using t = hodt.terrain(xyz, { dedupe: 'first' });
    expect(t.numInputPoints).toBe(6);
    expect(t.numPoints).toBe(5);
    expect(Array.from(t.vertexIndex)).toEqual([0, 1, 2, 4, 5]);
    const m = t.measures();
    expect(m.vertexClass[3]).toBe(VertexClass.Dropped);
    expect(m.degree[3]).toBe(0);
    expect(m.degree[5]).toBe(4);
  });
});

describe('higher order: useful edges and triangles', () => {
  it('order 1: the Delaunay edges plus the other diagonals of the quads', () => {
    let s = 5;
    const r = () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
    using t = hodt.terrain(Float64Array.from({ length: 300 }, r));
    const stats = t.stats(1);
    const edges = t.usefulEdges(1), triangles = t.usefulTriangles(1);
    expect(edges.length).toBe(2 * (stats.edges + t.numQuads));
    expect(triangles.length).toBeGreaterThanOrEqual(3 * (stats.triangles + 2 * t.numQuads));
    expect(stats).toMatchObject({ order: 1, usefulEdges: edges.length / 2, usefulTriangles: triangles.length / 3 });
    expect(t.usefulEdges(3).length).toBeGreaterThan(edges.length);
    expect(() => t.usefulEdges(0)).toThrow('order is 0, expected an integer from 1 to 16');
    expect(t.stats().order).toBeUndefined();
  });
});
