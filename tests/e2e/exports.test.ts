// Exports of the demo (web/demo/src/io): the points CSV reads back to the same
// doubles with the library's own parser; OBJ and PLY list every point and
// triangle; the solution JSON has the CLI's keys in the CLI's order.
import { loadHodt, type Hodt } from 'hodt';
import { beforeAll, describe, expect, test } from 'vitest';
import { triangulationToObj, triangulationToPly } from '../../web/demo/src/io/meshFormats.ts';
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

  test('OBJ and PLY hold every point and triangle', () => {
    using terrain = hodt.terrain(points);
    const { triangles } = terrain.delaunay();
    const obj = triangulationToObj(points, triangles, 'test').split('\n');
    expect(obj.filter((l) => l.startsWith('v ')).length).toBe(5);
    const faces = obj.filter((l) => l.startsWith('f '));
    expect(faces.length).toBe(triangles.length / 3);
    expect(faces[0]).toBe(`f ${triangles[0]! + 1} ${triangles[1]! + 1} ${triangles[2]! + 1}`);
    const ply = triangulationToPly(points, triangles, 'test');
    expect(ply).toContain(`element vertex 5\n`);
    expect(ply).toContain(`element face ${triangles.length / 3}\n`);
    expect(ply.trim().split('\n').at(-1)).toBe(`3 ${triangles.at(-3)} ${triangles.at(-2)} ${triangles.at(-1)}`);
  });

  test("solution JSON has the CLI's keys and order", () => {
    using terrain = hodt.terrain(points);
    const s = terrain.solve('minmax-edge-area-ratio', { method: 'exact' });
    const doc = JSON.parse(solutionToJson(s));
    expect(Object.keys(doc).slice(0, 9)).toEqual(['objective', 'sense', 'method', 'value', 'delaunayValue', 'optimal', 'bound', 'flipped', 'timeMs']);
    expect(doc.value).toBe(s.value);
    expect(solutionToJson(s)).toMatch(/^\{"objective": "minmax-edge-area-ratio", "sense": "min", /);
  });
});
