// Plane and terrain geometry in doubles, for the teaching views. The library
// decides everything exactly; these mirror its formulas (core/src/measures.cpp)
// closely enough to show which pairs exceed a threshold the library tested.
import type { Tri } from './structure.ts';

type P = Float64Array;
const X = (p: P, i: number) => p[3 * i]!;
const Y = (p: P, i: number) => p[3 * i + 1]!;
const Z = (p: P, i: number) => p[3 * i + 2]!;

/** Rotates a triangle to start at its lexicographically smallest corner (as the
 * core does), so that its measures do not depend on how it is listed. */
function canonical(p: P, t: Tri): Tri {
  const less = (i: number, j: number) => X(p, i) < X(p, j) || (X(p, i) === X(p, j) && Y(p, i) < Y(p, j));
  const [a, b, c] = t;
  if (less(b, a) && less(b, c)) return [b, c, a];
  if (less(c, a) && less(c, b)) return [c, a, b];
  return t;
}

export function triangleArea(p: P, t: Tri): number {
  const [a, b, c] = canonical(p, t);
  return Math.abs(0.5 * ((X(p, b) - X(p, a)) * (Y(p, c) - Y(p, a)) - (Y(p, b) - Y(p, a)) * (X(p, c) - X(p, a))));
}

export function areaRatio(p: P, s: Tri, t: Tri): number {
  const a1 = triangleArea(p, s);
  const a2 = triangleArea(p, t);
  return a1 > a2 ? a1 / a2 : a2 / a1;
}

function upwardNormal(p: P, t: Tri): [number, number, number] {
  const [a, b, c] = canonical(p, t);
  const u = [X(p, b) - X(p, a), Y(p, b) - Y(p, a), Z(p, b) - Z(p, a)];
  const v = [X(p, c) - X(p, a), Y(p, c) - Y(p, a), Z(p, c) - Z(p, a)];
  const n: [number, number, number] = [u[1]! * v[2]! - u[2]! * v[1]!, u[2]! * v[0]! - u[0]! * v[2]!, u[0]! * v[1]! - u[1]! * v[0]!];
  return n[2] < 0 ? [-n[0], -n[1], -n[2]] : n;
}

export function normalAngle(p: P, s: Tri, t: Tri): number {
  const n = upwardNormal(p, s);
  const m = upwardNormal(p, t);
  const cx = n[1] * m[2] - n[2] * m[1];
  const cy = n[2] * m[0] - n[0] * m[2];
  const cz = n[0] * m[1] - n[1] * m[0];
  return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), n[0] * m[0] + n[1] * m[1] + n[2] * m[2]);
}

/** Radius of the smallest circle holding the triangle s and the corner of t
 * that is not in s. */
export function enclosingCircle(p: P, s: Tri, t: Tri): number {
  const d = t.find((v) => !s.includes(v)) ?? t[0];
  const q = [...s, d].map((i) => [X(p, i), Y(p, i)] as const);
  const inside = (cx: number, cy: number, r: number) => q.every(([x, y]) => Math.hypot(x - cx, y - cy) <= r * (1 + 1e-12) + 1e-300);
  let best = Infinity;
  for (let i = 0; i < 4; i++) {
    for (let j = i + 1; j < 4; j++) {
      const [ax, ay] = q[i]!;
      const [bx, by] = q[j]!;
      const r = 0.5 * Math.hypot(bx - ax, by - ay);
      if (inside((ax + bx) / 2, (ay + by) / 2, r)) best = Math.min(best, r);
    }
  }
  for (let skip = 0; skip < 4; skip++) {
    const [a, b, c] = q.filter((_, k) => k !== skip) as [readonly [number, number], readonly [number, number], readonly [number, number]];
    const d2 = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    if (d2 === 0) continue;
    const s1 = a[0] * a[0] + a[1] * a[1];
    const s2 = b[0] * b[0] + b[1] * b[1];
    const s3 = c[0] * c[0] + c[1] * c[1];
    const cx = (s1 * (b[1] - c[1]) + s2 * (c[1] - a[1]) + s3 * (a[1] - b[1])) / d2;
    const cy = (s1 * (c[0] - b[0]) + s2 * (a[0] - c[0]) + s3 * (b[0] - a[0])) / d2;
    const r = Math.hypot(a[0] - cx, a[1] - cy);
    if (inside(cx, cy, r)) best = Math.min(best, r);
  }
  return best;
}

/** Shape of edge u v with w on one side and x on the other: 0 convex (x below
 * the plane of u, v, w: a ridge), 1 reflex (above: a valley), 2 flat. */
export function edgeShape(p: P, u: number, v: number, w: number, x: number): 0 | 1 | 2 {
  const ax = X(p, v) - X(p, u), ay = Y(p, v) - Y(p, u), az = Z(p, v) - Z(p, u);
  const bx = X(p, w) - X(p, u), by = Y(p, w) - Y(p, u), bz = Z(p, w) - Z(p, u);
  const cx = X(p, x) - X(p, u), cy = Y(p, x) - Y(p, u), cz = Z(p, x) - Z(p, u);
  const o3 = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  const o2 = ax * by - ay * bx;
  const s = o3 * o2;
  return s < 0 ? 0 : s > 0 ? 1 : 2;
}

function orient2d(p: P, a: number, b: number, c: number): number {
  const d = (X(p, b) - X(p, a)) * (Y(p, c) - Y(p, a)) - (Y(p, b) - Y(p, a)) * (X(p, c) - X(p, a));
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

/** Sign of the determinant [b - a, c - a, d - a] (positive: d above the plane of
 * a counterclockwise triangle a, b, c). */
function orient3d(p: P, a: number, b: number, c: number, d: number): number {
  const ax = X(p, b) - X(p, a), ay = Y(p, b) - Y(p, a), az = Z(p, b) - Z(p, a);
  const bx = X(p, c) - X(p, a), by = Y(p, c) - Y(p, a), bz = Z(p, c) - Z(p, a);
  const cx = X(p, d) - X(p, a), cy = Y(p, d) - Y(p, a), cz = Z(p, d) - Z(p, a);
  const det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  return det > 0 ? 1 : det < 0 ? -1 : 0;
}

/** Is interior vertex v mixed among its neighbours nb (every plane through v has
 * neighbours strictly above and strictly below)? The core's vertex_class. */
export function isMixed(p: P, v: number, nb: readonly number[]): boolean {
  const d = nb.length;
  const o = new Int8Array(d * d);
  for (let i = 0; i < d; i++) {
    for (let j = i + 1; j < d; j++) {
      const s = orient2d(p, v, nb[i]!, nb[j]!);
      o[i * d + j] = s;
      o[j * d + i] = -s;
    }
  }
  let fi = -1, fj = -1;
  for (let i = 0; i < d && fi < 0; i++) {
    for (let j = i + 1; j < d; j++) {
      if (o[i * d + j] !== 0) {
        fi = i;
        fj = j;
        break;
      }
    }
  }
  if (fi < 0) return false;
  let flat = true;
  for (let k = 0; k < d && flat; k++) flat = k === fi || k === fj || orient3d(p, v, nb[fi]!, nb[fj]!, nb[k]!) === 0;
  if (flat) return false;
  let below = false, above = false;
  for (let i = 0; i < d; i++) {
    for (let j = i + 1; j < d; j++) {
      for (let k = j + 1; k < d; k++) {
        const s = orient2d(p, nb[i]!, nb[j]!, nb[k]!);
        if (s === 0) continue;
        if (o[i * d + j]! * s < 0 || o[j * d + k]! * s < 0 || o[k * d + i]! * s < 0) continue;
        const h = orient3d(p, nb[i]!, nb[j]!, nb[k]!, v) * s;
        if (h < 0) below = true;
        if (h > 0) above = true;
        if (below && above) return true;
      }
    }
  }
  return false;
}
