// docs/api.md "Writing files": a solved terrain as PLY, glTF and GeoJSON.
import { writeFileSync } from 'node:fs';
import { loadHodt } from 'hodt';
import { exportMesh, nonDelaunayTriangles, toGeoJSON } from 'hodt/export';

const hodt = await loadHodt();
const utm = [731012.3456789, 5501234.5, 12, 731112.5, 5501234.25, 10, 731062, 5501334.5, 7.5, 731050, 5501260, 30];
using terrain = hodt.terrain(utm);
const best = terrain.solve('min-local-minima');
const { vertexClass, extremum } = terrain.measuresOfTriangles(best.triangles);
const mesh = {
  points: terrain.points, // written exactly as given
  triangles: best.triangles,
  vertexClass, // PLY: uchar class
  extremum, // PLY: uchar extremum
  nonDelaunay: nonDelaunayTriangles(best.triangles, terrain.delaunay().triangles), // PLY: non_delaunay
  comment: `min-local-minima = ${best.value}`,
};
writeFileSync('tin.ply', exportMesh('ply', mesh)); // binary little endian, doubles
writeFileSync('tin.glb', exportMesh('glb', mesh)); // glTF 2.0 for 3D viewers
const geojson = JSON.parse(toGeoJSON(mesh)); // one Polygon feature per triangle
console.log(geojson.features.length, geojson.features[0].geometry.coordinates[0][0]);
