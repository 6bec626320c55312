// hodt/export: every format read back by the independent readers of
// meshReaders.ts, on a solved terrain with UTM-like coordinates.
import { beforeAll, describe, expect, it } from 'vitest';
import {
  exportMesh,
  exportMeshParts,
  MESH_FORMATS,
  type MeshData,
  meshFormatOf,
  nonDelaunayTriangles,
  toGeoJSON,
  toGLB,
  toOBJ,
  toPLY,
} from '../../web/src/export.js';
import { type Hodt, InputError, loadHodt } from '../../web/src/index.js';
import { float32HalfUlp, readGLB, readOBJ, readPLY } from './meshReaders.js';

let hodt: Hodt;
let mesh: Required<MeshData> & { points: Float64Array; triangles: Uint32Array };
let flipped: number;

// 300 points a few hundred metres apart in UTM zone 32 (metres, seven decimals),
// the first at x = 731012.3456789.
function utmPoints(n: number): Float64Array {
  let s = 7;
  const r = () => ((s = (s * 1664525 + 1013904223) >>> 0) / 4294967296);
  const xyz = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    xyz[3 * i] = i === 0 ? 731012.3456789 : Math.round((731012 + 800 * r()) * 1e7) / 1e7;
    xyz[3 * i + 1] = Math.round((5501234 + 800 * r()) * 1e7) / 1e7;
    xyz[3 * i + 2] = Math.round(200 * r() * 1e4) / 1e4 + 0.1;
  }
  return xyz;
}

beforeAll(async () => {
  hodt = await loadHodt();
  using terrain = hodt.terrain(utmPoints(300));
  const best = terrain.solve('max-convex-edges', { method: 'exact' });
  expect(best.flipped).toBeGreaterThan(0); // some triangles are not Delaunay ones
  flipped = best.flipped;
  const measures = terrain.measures(best.choice);
  mesh = {
    points: terrain.points,
    triangles: best.triangles,
    vertexClass: measures.vertexClass,
    extremum: measures.extremum,
    nonDelaunay: nonDelaunayTriangles(best.triangles, terrain.delaunay().triangles),
    comment: 'test mesh\nsecond line',
  };
});

describe('OBJ', () => {
  it('one v line per point with the shortest round-trip decimals, one f line per triangle', () => {
    const obj = readOBJ(toOBJ(mesh));
    expect(obj.points).toEqual(Array.from(mesh.points));
    expect(obj.tokens[0]).toBe('731012.3456789');
    expect(obj.tokens).toEqual(Array.from(mesh.points, String));
    expect(obj.triangles).toEqual(Array.from(mesh.triangles));
    expect(obj.comments[0]).toBe('test mesh second line');
  });
});

describe('PLY', () => {
  it('binary little endian: doubles, vertex class and extremum, faces with the non-Delaunay flag', () => {
    const ply = readPLY(toPLY(mesh));
    const { vertex, face } = ply.elements;
    expect(vertex!.count).toBe(300);
    expect(face!.count).toBe(mesh.triangles.length / 3);
    expect(vertex!.properties.map((p) => `${p.type} ${p.name}`)).toEqual(['double x', 'double y', 'double z', 'uchar class', 'uchar extremum']);
    expect(face!.properties.map((p) => `${p.countType ?? ''} ${p.type} ${p.name}`)).toEqual([
      'uchar uint vertex_indices',
      ' uchar non_delaunay',
    ]);
    expect(vertex!.rows.flatMap((r) => [r.x, r.y, r.z])).toEqual(Array.from(mesh.points));
    expect(vertex!.rows.map((r) => r.class)).toEqual(Array.from(mesh.vertexClass));
    expect(vertex!.rows.map((r) => r.extremum)).toEqual(Array.from(mesh.extremum));
    expect(face!.rows.flatMap((r) => r.vertex_indices as number[])).toEqual(Array.from(mesh.triangles));
    const nonDelaunay = face!.rows.map((r) => r.non_delaunay as number);
    expect(nonDelaunay).toEqual(Array.from(mesh.nonDelaunay));
    // Each flipped quad puts two triangles not in the Delaunay triangulation.
    expect(nonDelaunay.filter((f) => f === 1)).toHaveLength(2 * flipped);
    expect(ply.comments).toContain('test mesh second line');
    expect(ply.comments.some((c) => c.startsWith('class: 0 convex, 1 concave'))).toBe(true);
  });

  it('leaves out the attributes not given', () => {
    const { vertex, face } = readPLY(toPLY({ points: mesh.points, triangles: mesh.triangles })).elements;
    expect(vertex!.properties.map((p) => p.name)).toEqual(['x', 'y', 'z']);
    expect(face!.properties.map((p) => p.name)).toEqual(['vertex_indices']);
  });
});

describe('GeoJSON', () => {
  it('a FeatureCollection of closed counterclockwise triangles with z, index, area and the Delaunay flag', () => {
    const doc = JSON.parse(toGeoJSON(mesh));
    expect(doc.type).toBe('FeatureCollection');
    expect(doc.features).toHaveLength(mesh.triangles.length / 3);
    const p = mesh.points;
    doc.features.forEach((f: any, k: number) => {
      expect(f.type).toBe('Feature');
      expect(f.geometry.type).toBe('Polygon');
      const [ring] = f.geometry.coordinates;
      expect(ring).toHaveLength(4);
      expect(ring[3]).toEqual(ring[0]);
      const corners = [0, 1, 2].map((c) => mesh.triangles[3 * k + c]!);
      const expected = corners.map((i) => [p[3 * i], p[3 * i + 1], p[3 * i + 2]]);
      // The same corners in the same cyclic order.
      const shift = expected.findIndex((e) => e[0] === ring[0][0] && e[1] === ring[0][1]);
      expect(ring.slice(0, 3)).toEqual([0, 1, 2].map((c) => expected[(shift + c) % 3]));
      const [a, b, c] = ring;
      const twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      expect(twice).toBeGreaterThan(0);
      expect(f.properties.index).toBe(k);
      expect(f.properties.area).toBeCloseTo(twice / 2, 6);
      expect(f.properties.delaunay).toBe(mesh.nonDelaunay[k] === 0);
    });
    expect(toGeoJSON(mesh)).toContain('[731012.3456789,');
  });
});

describe('glTF binary', () => {
  it('one mesh: float32 positions around the centre, which is the node translation; uint32 indices', () => {
    const { gltf, chunks, accessor } = readGLB(toGLB(mesh));
    expect(chunks).toHaveLength(2);
    expect(gltf.asset.version).toBe('2.0');
    expect(gltf.meshes).toHaveLength(1);
    const [primitive] = gltf.meshes[0].primitives;
    expect(primitive.mode).toBe(4);
    const position = gltf.accessors[primitive.attributes.POSITION];
    const index = gltf.accessors[primitive.indices];
    expect(position).toMatchObject({ componentType: 5126, type: 'VEC3', count: 300 });
    expect(index).toMatchObject({ componentType: 5125, type: 'SCALAR', count: mesh.triangles.length });
    expect(accessor(primitive.indices)).toEqual(Array.from(mesh.triangles));

    // The terrain node (x, y, z as given) under a node turning z up into y up.
    const [root] = gltf.scenes[gltf.scene].nodes.map((i: number) => gltf.nodes[i]);
    expect(root.rotation).toEqual([-Math.SQRT1_2, 0, 0, Math.SQRT1_2]);
    const node = gltf.nodes[root.children[0]];
    expect(node.mesh).toBe(0);
    const t: number[] = node.translation;
    const positions = accessor(primitive.attributes.POSITION);
    const p = mesh.points;
    for (let i = 0; i < p.length; i++) {
      const offset = p[i]! - t[i % 3]!;
      expect(Math.abs(positions[i]! - offset)).toBeLessThanOrEqual(float32HalfUlp(offset));
      // As exact as float32 allows: within a millimetre here, though x is about 731 km.
      expect(Math.abs(t[i % 3]! + positions[i]! - p[i]!)).toBeLessThan(1e-3);
    }
    for (let a = 0; a < 3; a++) {
      const values = positions.filter((_, i) => i % 3 === a);
      expect(position.min[a]).toBe(Math.min(...values));
      expect(position.max[a]).toBe(Math.max(...values));
    }
  });
});

describe('exportMesh', () => {
  it('gives the bytes of each format', () => {
    const decode = (b: Uint8Array) => new TextDecoder().decode(b);
    expect(decode(exportMesh('obj', mesh))).toBe(toOBJ(mesh));
    expect(decode(exportMesh('geojson', mesh))).toBe(toGeoJSON(mesh));
    expect(exportMesh('ply', mesh)).toEqual(toPLY(mesh));
    expect(exportMesh('glb', mesh)).toEqual(toGLB(mesh));
    expect(() => exportMesh('stl' as 'obj', mesh)).toThrow(InputError);
  });

  it('gives the file in parts for streaming: text in parts of a few thousand lines', () => {
    // A 100 x 100 grid: 19,602 triangles.
    const side = 100;
    const points = Float64Array.from({ length: 3 * side * side }, (_, i) => (i % 3 === 2 ? i % 7 : i % 3 === 0 ? Math.floor(i / 3) % side : Math.floor(i / 3 / side)));
    const triangles: number[] = [];
    for (let r = 0; r + 1 < side; r++) {
      for (let c = 0; c + 1 < side; c++) {
        const v = r * side + c;
        triangles.push(v, v + 1, v + side + 1, v, v + side + 1, v + side);
      }
    }
    const big = { points, triangles };
    const parts = Array.from(exportMeshParts('geojson', big)) as string[];
    expect(parts.length).toBeGreaterThan(4);
    expect(parts.join('')).toBe(toGeoJSON(big));
    expect(JSON.parse(parts.join('')).features).toHaveLength(triangles.length / 3);
    expect((Array.from(exportMeshParts('obj', big)) as string[]).join('')).toBe(toOBJ(big));
    expect(Array.from(exportMeshParts('ply', big))).toEqual([toPLY(big)]);
    // The mesh is checked when the parts are asked for, before any is written.
    expect(() => exportMeshParts('obj', { points, triangles: [0, 1] })).toThrow(InputError);
  });

  it('knows the formats by file extension', () => {
    expect(meshFormatOf('tin.OBJ')).toBe('obj');
    expect(meshFormatOf('/data/tin.geojson')).toBe('geojson');
    expect(meshFormatOf('tin.glb')).toBe('glb');
    expect(meshFormatOf('tin.ply')).toBe('ply');
    expect(meshFormatOf('tin.json')).toBeNull();
    expect(Object.keys(MESH_FORMATS)).toEqual(['obj', 'ply', 'geojson', 'glb']);
  });

  it('refuses a broken mesh with an InputError naming what is wrong', () => {
    const { points, triangles } = mesh;
    expect(() => toOBJ({ points: points.subarray(1), triangles })).toThrow(/points has 899 numbers/);
    expect(() => toPLY({ points, triangles: [0, 1, 300] })).toThrow(/triangle 0: point index 300 is not a point \(there are 300\)/);
    expect(() => toGLB({ points: [0, 0, NaN, 1, 0, 0, 0, 1, 0], triangles: [0, 1, 2] })).toThrow(/point 0: z is NaN/);
    expect(() => toGeoJSON({ points, triangles, nonDelaunay: [1] })).toThrow(InputError);
    expect(() => toPLY({ points, triangles, vertexClass: new Array(300).fill(256) })).toThrow(/vertexClass\[0\] is 256/);
  });
});

describe('nonDelaunayTriangles', () => {
  it('marks the triangles that are not in the other triangulation, however their corners are listed', () => {
    const delaunay = [0, 1, 2, 0, 2, 3];
    expect(Array.from(nonDelaunayTriangles([2, 0, 1, 3, 0, 2], delaunay))).toEqual([0, 0]);
    expect(Array.from(nonDelaunayTriangles([0, 1, 3, 1, 2, 3], delaunay))).toEqual([1, 1]);
    expect(Array.from(nonDelaunayTriangles([0, 2, 1], delaunay))).toEqual([1]); // clockwise is another triangle
  });
});
