// GeoJSON: the triangles as Polygon features with 3D coordinates.
import { checkMesh, type MeshData } from './meshData.js';
import { LineBatch } from './text.js';

/** The GeoJSON text in parts (see text.ts); the mesh is checked at once. */
export function geojsonParts(mesh: MeshData): Iterable<string> {
  return geojsonText(mesh, checkMesh(mesh).triangles);
}

function* geojsonText(mesh: MeshData, m: number): Generator<string> {
  const { points: p, triangles: t, nonDelaunay, outside } = mesh;
  const at = (i: number) => `[${String(p[3 * i])},${String(p[3 * i + 1])},${String(p[3 * i + 2])}]`;
  const out = new LineBatch();
  // A named CRS (the GeoJSON 2008 member RFC 7946 dropped; GDAL and QGIS read it).
  const epsg = /^EPSG:(\d+)$/.exec(mesh.crs ?? '');
  const crs = epsg ? `"crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::${epsg[1]}"}},` : '';
  out.add(`{"type":"FeatureCollection",${crs}"features":[`);
  for (let k = 0; k < m; k++) {
    let a = t[3 * k]!, b = t[3 * k + 1]!;
    const c = t[3 * k + 2]!;
    // Plane area, from the first corner (keeps the digits of large coordinates).
    const ax = p[3 * a]!, ay = p[3 * a + 1]!;
    const twice = (p[3 * b]! - ax) * (p[3 * c + 1]! - ay) - (p[3 * b + 1]! - ay) * (p[3 * c]! - ax);
    if (twice < 0) [a, b] = [b, a]; // RFC 7946: exterior rings counterclockwise
    const properties = `"index":${k},"area":${String(Math.abs(twice) / 2)}` +
      (nonDelaunay ? `,"delaunay":${nonDelaunay[k] === 0}` : '') +
      (outside ? `,"inside":${outside[k] === 0}` : '');
    const feature =
      `{"type":"Feature","properties":{${properties}},"geometry":{"type":"Polygon","coordinates":[[${at(a)},${at(b)},${at(c)},${at(a)}]]}}` +
      (k + 1 < m ? ',' : '');
    if (out.add(feature)) yield out.take();
  }
  out.add(']}');
  yield out.take();
}

/**
 * A GeoJSON FeatureCollection with one Polygon feature per triangle: its ring is
 * the three corners [x, y, z] and the first again, counterclockwise, each number
 * the shortest decimal that reads back to the same double. Properties: `index`
 * (the triangle's), `area` (plane area, in squared plane units) and, when
 * `nonDelaunay` is given, `delaunay` (true for a triangle of the Delaunay
 * triangulation) and, when `outside` is given, `inside` (false for a triangle
 * outside the domain). Coordinates are written as given: GeoJSON (RFC 7946) expects
 * longitude and latitude, so tell your GIS the coordinate system of projected
 * data (for example UTM).
 */
export function toGeoJSON(mesh: MeshData): string {
  return Array.from(geojsonParts(mesh)).join('');
}
