// hodt/three against the real three.js (in Node: BufferGeometry needs no WebGL).
import * as THREE from 'three';
import { beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, InputError, loadHodt } from '../../web/src/index.js';
import { setTriangles, terrainGeometry } from '../../web/src/three.js';
import { randomPoints } from './randomPoints.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

describe('terrainGeometry', () => {
  it('makes an indexed BufferGeometry with positions and normals', () => {
    using t = hodt.terrain(randomPoints(200, 3));
    const triangles = t.delaunay().triangles;
    const g = terrainGeometry(THREE, t.points, triangles);
    expect(g).toBeInstanceOf(THREE.BufferGeometry);
    expect(g.getAttribute('position').count).toBe(200);
    expect(g.getAttribute('normal').count).toBe(200);
    expect(Array.from(g.getIndex()!.array)).toEqual(Array.from(triangles));
    // Counterclockwise seen from +z: normals point up.
    const normal = g.getAttribute('normal');
    for (let i = 0; i < normal.count; ++i) expect(normal.getZ(i)).toBeGreaterThan(0);
  });

  it("up: 'y' rotates heights to +y and keeps the winding", () => {
    const xyz = Float64Array.from([0, 0, 5, 1, 0, 6, 0, 1, 7]);
    const g = terrainGeometry(THREE, xyz, Uint32Array.from([0, 1, 2]), { up: 'y', origin: [0, 0, 5] });
    const p = g.getAttribute('position');
    expect([p.getX(1), p.getY(1), p.getZ(1)]).toEqual([1, 1, -0]);
    expect([p.getX(2), p.getY(2), p.getZ(2)]).toEqual([0, 2, -1]);
    // Surface facing +y: the normal of a flat-ish triangle has a positive y.
    expect(g.getAttribute('normal').getY(0)).toBeGreaterThan(0);
  });

  it('setTriangles swaps in a solution in place', () => {
    using t = hodt.terrain(randomPoints(300, 4));
    const g = terrainGeometry(THREE, t.points, t.delaunay().triangles);
    const index = g.getIndex()!;
    const version = index.version;
    const best = t.solve('min-total-edge-length');
    setTriangles(g, best.triangles);
    expect(g.getIndex()).toBe(index);
    expect(index.version).toBeGreaterThan(version);
    expect(Array.from(index.array)).toEqual(Array.from(best.triangles));
    expect(() => setTriangles(g, best.triangles.subarray(3))).toThrow(InputError);
  });

  it('rejects triangles that refer to missing points', () => {
    expect(() => terrainGeometry(THREE, [0, 0, 0, 1, 0, 0, 0, 1, 0], Uint32Array.from([0, 1, 3]))).toThrow(/point 3/);
  });
});
