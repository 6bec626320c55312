// Binary glTF 2.0 (.glb): one mesh of float32 positions and uint32 indices.
import { checkMesh, type MeshData, oneLine } from './meshData.js';

const FLOAT = 5126, UNSIGNED_INT = 5125, ARRAY_BUFFER = 34962, ELEMENT_ARRAY_BUFFER = 34963, TRIANGLES = 4;
const JSON_CHUNK = 0x4e4f534a, BIN_CHUNK = 0x004e4942, MAGIC = 0x46546c67;

/**
 * Binary glTF 2.0: one mesh with one primitive, POSITION (float32) and indices
 * (uint32), counterclockwise seen from above.
 *
 * Float32 holds about 7 digits, too few for coordinates such as UTM metres, so
 * positions are stored relative to the centre of the points' bounding box and the
 * centre itself is the translation of the mesh's node (a JSON number: a double,
 * exact). Each coordinate is then the translation plus the position, as exact as
 * float32 allows for the distance from the centre (half a millimetre at 5 km).
 * glTF's up axis is +y: the node with the mesh (named "terrain", x, y, z as given,
 * z up) is the child of a node that rotates z up to y up, so viewers show the
 * terrain lying flat. Attributes are not written.
 */
export function toGLB(mesh: MeshData): Uint8Array {
  const { points: n, triangles: m } = checkMesh(mesh);
  const { points: p, triangles: t } = mesh;
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < 3 * n; i++) {
    lo[i % 3] = Math.min(lo[i % 3]!, p[i]!);
    hi[i % 3] = Math.max(hi[i % 3]!, p[i]!);
  }
  const centre = n === 0 ? [0, 0, 0] : lo.map((l, a) => l / 2 + hi[a]! / 2);
  const positions = new Float32Array(3 * n);
  for (let i = 0; i < 3 * n; i++) positions[i] = p[i]! - centre[i % 3]!;
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < 3 * n; i++) {
    min[i % 3] = Math.min(min[i % 3]!, positions[i]!);
    max[i % 3] = Math.max(max[i % 3]!, positions[i]!);
  }
  const indices = Uint32Array.from(t);

  const positionBytes = positions.byteLength, indexBytes = indices.byteLength;
  const gltf = {
    asset: {
      version: '2.0',
      generator: 'hodt',
      ...(mesh.comment || mesh.crs
        ? { extras: { ...(mesh.comment ? { comment: oneLine(mesh.comment) } : {}), ...(mesh.crs ? { crs: oneLine(mesh.crs) } : {}) } }
        : {}),
    },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [
      { name: 'z up to y up', rotation: [-Math.SQRT1_2, 0, 0, Math.SQRT1_2], children: [1] },
      { name: 'terrain', translation: centre, mesh: 0 },
    ],
    meshes: [{ name: 'terrain', primitives: [{ attributes: { POSITION: 0 }, indices: 1, mode: TRIANGLES }] }],
    accessors: [
      { bufferView: 0, componentType: FLOAT, count: n, type: 'VEC3', ...(n > 0 ? { min, max } : {}) },
      { bufferView: 1, componentType: UNSIGNED_INT, count: 3 * m, type: 'SCALAR' },
    ],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: positionBytes, target: ARRAY_BUFFER },
      { buffer: 0, byteOffset: positionBytes, byteLength: indexBytes, target: ELEMENT_ARRAY_BUFFER },
    ],
    buffers: [{ byteLength: positionBytes + indexBytes }],
  };
  const json = new TextEncoder().encode(JSON.stringify(gltf));
  const jsonLength = align4(json.length), binLength = positionBytes + indexBytes; // both multiples of 4
  const out = new Uint8Array(12 + 8 + jsonLength + 8 + binLength);
  const view = new DataView(out.buffer);
  view.setUint32(0, MAGIC, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, out.length, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, JSON_CHUNK, true);
  out.set(json, 20);
  out.fill(0x20, 20 + json.length, 20 + jsonLength); // the JSON chunk is padded with spaces
  const bin = 20 + jsonLength;
  view.setUint32(bin, binLength, true);
  view.setUint32(bin + 4, BIN_CHUNK, true);
  out.set(new Uint8Array(positions.buffer), bin + 8);
  out.set(new Uint8Array(indices.buffer), bin + 8 + positionBytes);
  return out;
}

function align4(n: number): number {
  return (n + 3) & ~3;
}
