// Readers of the mesh formats, written from the format specifications and
// independent of the writers in web/src/export: the tests parse every file back
// with them.

export interface ReadMesh {
  points: number[];
  triangles: number[];
}

/** Wavefront OBJ: `v x y z` and `f i j k` lines (1-based), `#` comments. */
export function readOBJ(text: string): ReadMesh & { tokens: string[]; comments: string[] } {
  const points: number[] = [], triangles: number[] = [], tokens: string[] = [], comments: string[] = [];
  for (const line of text.split('\n')) {
    if (line === '') continue;
    const [kind, ...fields] = line.split(' ');
    if (kind === '#') comments.push(fields.join(' '));
    else if (kind === 'v') {
      if (fields.length !== 3) throw new Error(`OBJ: bad vertex line ${line}`);
      tokens.push(...fields);
      points.push(...fields.map(Number));
    } else if (kind === 'f') {
      if (fields.length !== 3) throw new Error(`OBJ: bad face line ${line}`);
      triangles.push(...fields.map((f) => Number(f) - 1));
    } else throw new Error(`OBJ: unexpected line ${line}`);
  }
  return { points, triangles, tokens, comments };
}

interface PlyProperty {
  name: string;
  type: string;
  countType?: string; // lists
}
interface PlyElement {
  name: string;
  count: number;
  properties: PlyProperty[];
  rows: Record<string, number | number[]>[];
}

const PLY_TYPES: Record<string, [number, (v: DataView, at: number) => number]> = {
  char: [1, (v, a) => v.getInt8(a)],
  uchar: [1, (v, a) => v.getUint8(a)],
  short: [2, (v, a) => v.getInt16(a, true)],
  ushort: [2, (v, a) => v.getUint16(a, true)],
  int: [4, (v, a) => v.getInt32(a, true)],
  uint: [4, (v, a) => v.getUint32(a, true)],
  float: [4, (v, a) => v.getFloat32(a, true)],
  double: [8, (v, a) => v.getFloat64(a, true)],
};

/** PLY, binary little endian (any elements and scalar or list properties). */
export function readPLY(bytes: Uint8Array): { comments: string[]; elements: Record<string, PlyElement> } {
  const end = new TextDecoder('latin1').decode(bytes.subarray(0, Math.min(bytes.length, 4096))).indexOf('end_header\n');
  if (end < 0) throw new Error('PLY: no end_header');
  const header = new TextDecoder().decode(bytes.subarray(0, end)).split('\n');
  if (header[0] !== 'ply' || header[1] !== 'format binary_little_endian 1.0') throw new Error('PLY: not binary little endian');
  const comments: string[] = [], order: PlyElement[] = [];
  for (const line of header.slice(2)) {
    const f = line.split(' ');
    if (f[0] === 'comment') comments.push(f.slice(1).join(' '));
    else if (f[0] === 'element') order.push({ name: f[1]!, count: Number(f[2]), properties: [], rows: [] });
    else if (f[0] === 'property' && f[1] === 'list') order.at(-1)!.properties.push({ name: f[4]!, type: f[3]!, countType: f[2]! });
    else if (f[0] === 'property') order.at(-1)!.properties.push({ name: f[2]!, type: f[1]! });
    else if (line !== '') throw new Error(`PLY: unexpected header line ${line}`);
  }
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let at = end + 'end_header\n'.length;
  const read = (type: string) => {
    const [size, get] = PLY_TYPES[type] ?? (() => { throw new Error(`PLY: type ${type}`); })();
    const v = get(view, at);
    at += size;
    return v;
  };
  for (const e of order) {
    for (let i = 0; i < e.count; i++) {
      const row: Record<string, number | number[]> = {};
      for (const p of e.properties) {
        if (p.countType) row[p.name] = Array.from({ length: read(p.countType) }, () => read(p.type));
        else row[p.name] = read(p.type);
      }
      e.rows.push(row);
    }
  }
  if (at !== bytes.length) throw new Error(`PLY: ${bytes.length - at} bytes after the last element`);
  return { comments, elements: Object.fromEntries(order.map((e) => [e.name, e])) };
}

/** Binary glTF 2.0: header, JSON and BIN chunks, and the accessors' data. */
export function readGLB(bytes: Uint8Array) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (view.getUint32(0, true) !== 0x46546c67) throw new Error('GLB: bad magic');
  if (view.getUint32(4, true) !== 2) throw new Error('GLB: not version 2');
  if (view.getUint32(8, true) !== bytes.length) throw new Error('GLB: length differs from the file size');
  const chunks: { type: number; data: Uint8Array }[] = [];
  for (let at = 12; at < bytes.length; ) {
    const length = view.getUint32(at, true), type = view.getUint32(at + 4, true);
    if (length % 4 !== 0) throw new Error('GLB: chunk not 4-byte aligned');
    chunks.push({ type, data: bytes.subarray(at + 8, at + 8 + length) });
    at += 8 + length;
  }
  if (chunks[0]?.type !== 0x4e4f534a || chunks[1]?.type !== 0x004e4942) throw new Error('GLB: expected a JSON then a BIN chunk');
  const gltf = JSON.parse(new TextDecoder().decode(chunks[0].data));
  const bin = chunks[1].data;
  const accessor = (i: number): number[] => {
    const a = gltf.accessors[i], bv = gltf.bufferViews[a.bufferView];
    const width = { SCALAR: 1, VEC3: 3 }[a.type as 'SCALAR' | 'VEC3'];
    const start = bin.byteOffset + (bv.byteOffset ?? 0) + (a.byteOffset ?? 0);
    const d = new DataView(bin.buffer, start, a.count * width * 4);
    return Array.from({ length: a.count * width }, (_, k) =>
      a.componentType === 5126 ? d.getFloat32(4 * k, true) : a.componentType === 5125 ? d.getUint32(4 * k, true) : NaN,
    );
  };
  return { gltf, chunks, accessor };
}

/** Half the float32 spacing at |v|: how far a float32 may be from v. */
export function float32HalfUlp(v: number): number {
  const e = Math.floor(Math.log2(Math.max(Math.abs(v), 2 ** -126)));
  return 2 ** (e - 23) / 2;
}
