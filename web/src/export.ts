/**
 * hodt/export: a triangulation as a file, for GIS tools, 3D viewers and meshing
 * software. No wasm: it works on arrays (the points and a solution's triangles),
 * for example exportMesh('ply', { points: terrain.points, triangles: best.triangles }).
 *
 * Reference: docs/api.md, "Writing files".
 */
import { InputError } from './errors.js';
import { geojsonParts } from './export/geojson.js';
import type { MeshData, MeshFormat } from './export/meshData.js';
import { toGLB } from './export/glb.js';
import { objParts } from './export/obj.js';
import { toPLY } from './export/ply.js';
import { concatParts } from './export/text.js';

export type { MeshData, MeshFormat } from './export/meshData.js';
export { toGeoJSON } from './export/geojson.js';
export { toGLB } from './export/glb.js';
export { nonDelaunayTriangles } from './export/nonDelaunay.js';
export { toOBJ } from './export/obj.js';
export { toPLY } from './export/ply.js';

/** The formats, each with its file extension and media type. */
export const MESH_FORMATS: Readonly<Record<MeshFormat, { extension: string; mediaType: string }>> = Object.freeze({
  obj: { extension: '.obj', mediaType: 'model/obj' },
  ply: { extension: '.ply', mediaType: 'application/octet-stream' },
  geojson: { extension: '.geojson', mediaType: 'application/geo+json' },
  glb: { extension: '.glb', mediaType: 'model/gltf-binary' },
});

/** The format a file name asks for by its extension (any case), or null. */
export function meshFormatOf(fileName: string): MeshFormat | null {
  const name = fileName.toLowerCase();
  for (const [format, { extension }] of Object.entries(MESH_FORMATS)) {
    if (name.endsWith(extension)) return format as MeshFormat;
  }
  return null;
}

/** The file in parts, in order: text formats as strings of a few thousand lines
 * (write them as UTF-8), binary formats as one Uint8Array. For writing large
 * files to a stream without holding the whole file; the mesh is checked at once. */
export function exportMeshParts(format: MeshFormat, mesh: MeshData): Iterable<string | Uint8Array> {
  switch (format) {
    case 'obj':
      return objParts(mesh);
    case 'ply':
      return [toPLY(mesh)];
    case 'geojson':
      return geojsonParts(mesh);
    case 'glb':
      return [toGLB(mesh)];
    default:
      throw new InputError(`unknown format ${JSON.stringify(String(format))}; expected obj, ply, geojson or glb`);
  }
}

/** The bytes of the file: toOBJ, toPLY, toGeoJSON or toGLB, text as UTF-8 (also
 * when the text is longer than the longest JavaScript string). */
export function exportMesh(format: MeshFormat, mesh: MeshData): Uint8Array {
  return concatParts(exportMeshParts(format, mesh));
}
