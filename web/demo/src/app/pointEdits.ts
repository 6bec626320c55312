/** Point edits as pure functions: each returns a new x, y, z array. */

export function addPoint(xyz: Float64Array, x: number, y: number, z: number): Float64Array {
  const out = new Float64Array(xyz.length + 3);
  out.set(xyz);
  out.set([x, y, z], xyz.length);
  return out;
}

export function movePoint(xyz: Float64Array, i: number, x: number, y: number, z: number): Float64Array {
  const out = xyz.slice();
  out[3 * i] = x;
  out[3 * i + 1] = y;
  out[3 * i + 2] = z;
  return out;
}

export function removePoint(xyz: Float64Array, i: number): Float64Array {
  const out = new Float64Array(xyz.length - 3);
  out.set(xyz.subarray(0, 3 * i));
  out.set(xyz.subarray(3 * i + 3), 3 * i);
  return out;
}

export function pointAt(xyz: Float64Array, i: number): { x: number; y: number; z: number } {
  return { x: xyz[3 * i]!, y: xyz[3 * i + 1]!, z: xyz[3 * i + 2]! };
}
