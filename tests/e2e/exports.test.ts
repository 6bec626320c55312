// Exports of the demo (web/demo/src/io): the points CSV reads back to the same
// doubles with the library's own parser; the mesh files (the library's writers,
// hodt/export) hold every point, triangle and attribute the views show; the
// solution JSON has the CLI's keys in the CLI's order.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { analyse, analyseTriangles, readStructure } from '../../web/demo/src/app/analysis.ts';
import { meshFile } from '../../web/demo/src/io/meshExport.ts';
import { readOBJ, readPLY } from '../js/meshReaders.ts';
import { pointsToCsv } from '../../web/demo/src/io/pointsCsv.ts';
import { solutionToJson } from '../../web/demo/src/io/solutionJson.ts';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

const points = Float64Array.from([0, 0, 1.5, 10, 0, -2.25, 10, 10, 1 / 3, 0, 10, 1e-40, 4.000000000000001, 6, 9]);

describe('exports', () => {
  test('points CSV reads back bit for bit', () => {
    const back = hodt.readPoints(pointsToCsv(points), 'points.csv').points;
    expect(Array.from(back)).toEqual(Array.from(points));
  });

  test('OBJ, PLY, GeoJSON and glTF hold every point and triangle; PLY the classes and flipped triangles', () => {
    using terrain = hodt.terrain(points);
    const structure = readStructure(terrain);
    expect(terrain.numQuads).toBeGreaterThan(0);
    const choice = new Uint8Array(terrain.numQuads).fill(1);
    const shown = analyse(terrain, structure, points, choice);
    const obj = readOBJ(new TextDecoder().decode(meshFile('obj', shown, 'test', false).bytes));
    expect(obj.points).toEqual(Array.from(points));
    expect(obj.triangles).toEqual(Array.from(shown.triangles));
    const ply = readPLY(meshFile('ply', shown, 'test', false).bytes).elements;
    expect(ply.vertex!.rows.map((r) => r.class)).toEqual(Array.from(shown.vertexClass));
    expect(ply.face!.rows.filter((r) => r.non_delaunay === 1)).toHaveLength(2 * terrain.numQuads);
    const geojson = meshFile('geojson', shown, 'test', false);
    expect(geojson.type).toBe('application/geo+json');
    expect(JSON.parse(new TextDecoder().decode(geojson.bytes)).features).toHaveLength(shown.triangles.length / 3);
    expect(meshFile('glb', shown, 'test', false).type).toBe('model/gltf-binary');
    // An order-k result marks its non-Delaunay triangles the same way.
    const k = analyseTriangles(terrain, structure, points, shown.triangles);
    expect(readPLY(meshFile('ply', k, 'test', false).bytes).elements.face!.rows.map((r) => r.non_delaunay)).toEqual(
      ply.face!.rows.map((r) => r.non_delaunay),
    );
  });

  test("solution JSON has the CLI's keys and order", () => {
    using terrain = hodt.terrain(points);
    const s = terrain.solve('minmax-edge-area-ratio', { method: 'exact' });
    const doc = JSON.parse(solutionToJson(s, terrain));
    expect(Object.keys(doc).slice(0, 9)).toEqual(['objective', 'sense', 'method', 'value', 'delaunayValue', 'optimal', 'bound', 'flipped', 'timeMs']);
    expect(doc.value).toBe(s.value);
    expect(solutionToJson(s, terrain)).toMatch(/^\{"objective": "minmax-edge-area-ratio", "sense": "min", /);
  });
});
