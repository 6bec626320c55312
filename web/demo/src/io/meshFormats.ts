/** Wavefront OBJ of a triangulation: one `v x y z` per point (input order) and
 * one `f` per triangle (1-based, counterclockwise seen from above). */
export function triangulationToObj(xyz: Float64Array, triangles: Uint32Array, comment: string): string {
  const out = [`# ${comment}`, `# ${xyz.length / 3} vertices, ${triangles.length / 3} triangles`];
  for (let i = 0; i < xyz.length; i += 3) out.push(`v ${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}`);
  for (let k = 0; k < triangles.length; k += 3) {
    out.push(`f ${triangles[k]! + 1} ${triangles[k + 1]! + 1} ${triangles[k + 2]! + 1}`);
  }
  return `${out.join('\n')}\n`;
}

/** ASCII PLY of a triangulation (double vertices, 0-based faces). */
export function triangulationToPly(xyz: Float64Array, triangles: Uint32Array, comment: string): string {
  const out = [
    'ply',
    'format ascii 1.0',
    `comment ${comment}`,
    `element vertex ${xyz.length / 3}`,
    'property double x',
    'property double y',
    'property double z',
    `element face ${triangles.length / 3}`,
    'property list uchar int vertex_indices',
    'end_header',
  ];
  for (let i = 0; i < xyz.length; i += 3) out.push(`${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}`);
  for (let k = 0; k < triangles.length; k += 3) out.push(`3 ${triangles[k]} ${triangles[k + 1]} ${triangles[k + 2]}`);
  return `${out.join('\n')}\n`;
}
