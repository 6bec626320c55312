// Section 4.1 of the paper in TypeScript, for display: the number of convex edges
// as a sum of factors over the quads (a factor per quad diagonal and per edge of
// the subdivision S), Baker's shifted layers, and an exact max-sum solver (variable
// elimination) for what each shift keeps. It mirrors the library's model
// (core/src/factor_models.cpp, baker.cpp) so that the bounds can be compared.
import { edgeShape, isMixed } from './geometry.ts';
import type { QuadStructure, Tri } from './structure.ts';

export interface Factor {
  /** Quads; bit j of a table index is the state of scope[j]. */
  scope: number[];
  table: number[];
}

export interface FactorGraph {
  numVars: number;
  constant: number;
  factors: Factor[];
}

const other = (t: Tri, u: number, v: number) => t.find((w) => w !== u && w !== v)!;

/** Convex edges as factors: each quad's diagonal (unary), each edge of S (unary
 * beside a fixed triangle, binary between two quads, constant between two fixed
 * triangles); then factors that do not depend on a quad drop it, as the core
 * simplifies them. */
export function convexEdgeModel(s: QuadStructure): FactorGraph {
  const p = s.points;
  const convex = (u: number, v: number, w: number, x: number) => (edgeShape(p, u, v, w, x) === 0 ? 1 : 0);
  const g: FactorGraph = { numVars: s.m, constant: 0, factors: [] };
  for (let q = 0; q < s.m; q++) {
    const [a, b, c, d] = [s.quads[4 * q]!, s.quads[4 * q + 1]!, s.quads[4 * q + 2]!, s.quads[4 * q + 3]!];
    g.factors.push({ scope: [q], table: [convex(a, b, c, d), convex(c, d, a, b)] });
  }
  for (const e of s.skeleton) {
    const { u, v, left: L, right: R } = e;
    const value = (x: number, y: number) => convex(u, v, other(L.tri[x]!, u, v), other(R.tri[y]!, u, v));
    if (L.quad < 0 && R.quad < 0) g.constant += value(0, 0);
    else if (R.quad < 0) g.factors.push({ scope: [L.quad], table: [value(0, 0), value(1, 0)] });
    else if (L.quad < 0) g.factors.push({ scope: [R.quad], table: [value(0, 0), value(0, 1)] });
    else g.factors.push({ scope: [L.quad, R.quad], table: [value(0, 0), value(1, 0), value(0, 1), value(1, 1)] });
  }
  simplify(g);
  return g;
}

/** Section 4.2: the number of non-mixed interior vertices as a sum of factors,
 * one per interior vertex over the quads at it (1 if not mixed), as the core
 * builds it (the fewest mixed vertices = interior - the most non-mixed). */
export function nonMixedModel(s: QuadStructure): { graph: FactorGraph; interior: number } {
  const p = s.points;
  const n = p.length / 3;
  const onHull = new Uint8Array(n);
  for (const v of s.hull) onHull[v] = 1;
  const neighbours: Set<number>[] = Array.from({ length: n }, () => new Set());
  const t = s.tri[0];
  for (let e = 0; e < t.length; e++) {
    const u = t[e]!, v = t[e % 3 === 2 ? e - 2 : e + 1]!;
    neighbours[u]!.add(v);
    neighbours[v]!.add(u);
  }
  const quadsAt: number[][] = Array.from({ length: n }, () => []);
  for (let q = 0; q < s.m; q++) for (let j = 0; j < 4; j++) quadsAt[s.quads[4 * q + j]!]!.push(q);
  const mixed: FactorGraph = { numVars: s.m, constant: 0, factors: [] };
  let interior = 0;
  for (let v = 0; v < n; v++) {
    if (onHull[v] || neighbours[v]!.size === 0) continue;
    interior++;
    const qs = quadsAt[v]!;
    const isDiagonal = (w: number) => qs.some((q) => (s.quads[4 * q] === v && s.quads[4 * q + 1] === w) || (s.quads[4 * q + 1] === v && s.quads[4 * q] === w));
    const fixed = [...neighbours[v]!].filter((w) => !isDiagonal(w));
    const table: number[] = [];
    for (let idx = 0; idx < 1 << qs.length; idx++) {
      const nb = fixed.slice();
      qs.forEach((q, i) => {
        const [a, b, c, d] = [s.quads[4 * q]!, s.quads[4 * q + 1]!, s.quads[4 * q + 2]!, s.quads[4 * q + 3]!];
        const flipped = (idx >> i) & 1;
        if (!flipped && (v === a || v === b)) nb.push(v === a ? b : a);
        if (flipped && (v === c || v === d)) nb.push(v === c ? d : c);
      });
      table.push(isMixed(p, v, nb) ? 1 : 0);
    }
    if (qs.length === 0) mixed.constant += table[0]!;
    else mixed.factors.push({ scope: qs.slice(), table });
  }
  simplify(mixed);
  const graph: FactorGraph = {
    numVars: s.m,
    constant: interior - mixed.constant - mixed.factors.length,
    factors: mixed.factors.map((f) => ({ scope: f.scope, table: f.table.map((x) => 1 - x) })),
  };
  return { graph, interior };
}

function simplify(g: FactorGraph): void {
  const kept: Factor[] = [];
  for (const f of g.factors) {
    for (let k = f.scope.length - 1; k >= 0; k--) {
      const bit = 1 << k;
      let depends = false;
      for (let i = 0; i < f.table.length && !depends; i++) depends = (i & bit) === 0 && f.table[i] !== f.table[i | bit];
      if (depends) continue;
      f.table = f.table.filter((_, i) => (i & bit) === 0);
      f.scope.splice(k, 1);
    }
    if (f.scope.length === 0) g.constant += f.table[0]!;
    else kept.push(f);
  }
  g.factors = kept;
}

export function evaluateFactors(g: FactorGraph, choice: ArrayLike<number>, keep?: (k: number) => boolean): number {
  let sum = g.constant;
  g.factors.forEach((f, k) => {
    if (keep && !keep(k)) return;
    let idx = 0;
    f.scope.forEach((v, j) => (idx |= (choice[v]! & 1) << j));
    sum += f.table[idx]!;
  });
  return sum;
}

export class TooWideError extends Error {}

/** Exact maximum of the sum of the given factors (plus the constant) by variable
 * elimination in min-degree order; throws TooWideError past maxWidth. */
export function maxSum(g: FactorGraph, factorIds: number[], maxWidth = 18): { value: number; choice: Uint8Array; width: number } {
  const n = g.numVars;
  type F = { scope: number[]; table: Float64Array };
  let live: (F | null)[] = factorIds.map((k) => ({ scope: g.factors[k]!.scope.slice(), table: Float64Array.from(g.factors[k]!.table) }));
  const byVar: Set<number>[] = Array.from({ length: n }, () => new Set());
  live.forEach((f, i) => f!.scope.forEach((v) => byVar[v]!.add(i)));
  const neighbours = (v: number) => {
    const s = new Set<number>();
    for (const i of byVar[v]!) for (const w of live[i]!.scope) if (w !== v) s.add(w);
    return s;
  };
  const remaining = new Set<number>();
  for (let v = 0; v < n; v++) if (byVar[v]!.size) remaining.add(v);
  const trail: { v: number; scope: number[]; arg: Uint8Array }[] = [];
  let width = 0;
  let constant = g.constant;
  while (remaining.size) {
    let best = -1, bestDegree = Infinity;
    for (const v of remaining) {
      const d = neighbours(v).size;
      if (d < bestDegree) (best = v), (bestDegree = d);
    }
    const v = best;
    remaining.delete(v);
    const bucket = [...byVar[v]!];
    const scope = [...neighbours(v)];
    width = Math.max(width, scope.length);
    if (scope.length > maxWidth) throw new TooWideError(`a thick layer is too wide for the browser (width ${scope.length})`);
    const size = 1 << scope.length;
    const table = new Float64Array(size);
    const arg = new Uint8Array(size);
    const full = [...scope, v];
    const maps = bucket.map((i) => live[i]!.scope.map((w) => full.indexOf(w)));
    for (let a = 0; a < size; a++) {
      let bestValue = -Infinity;
      for (let x = 0; x < 2; x++) {
        const idxFull = a | (x << scope.length);
        let sum = 0;
        bucket.forEach((i, j) => {
          const f = live[i]!;
          let idx = 0;
          maps[j]!.forEach((pos, b) => (idx |= ((idxFull >> pos) & 1) << b));
          sum += f.table[idx]!;
        });
        if (sum > bestValue) (bestValue = sum), (arg[a] = x);
      }
      table[a] = bestValue;
    }
    for (const i of bucket) {
      for (const w of live[i]!.scope) byVar[w]!.delete(i);
      live[i] = null;
    }
    trail.push({ v, scope, arg });
    if (scope.length === 0) constant += table[0]!;
    else {
      const id = live.length;
      live.push({ scope, table });
      for (const w of scope) byVar[w]!.add(id);
    }
  }
  live = [];
  const choice = new Uint8Array(n);
  for (let i = trail.length - 1; i >= 0; i--) {
    const { v, scope, arg } = trail[i]!;
    let a = 0;
    scope.forEach((w, b) => (a |= choice[w]! << b));
    choice[v] = arg[a]!;
  }
  return { value: constant, choice, width };
}

export interface BakerShift {
  shift: number;
  /** Factors (edges between quads) cut by this shift. */
  dropped: number[];
  /** Optimum of what the shift keeps (cut factors count 0). */
  relaxed: number;
  /** Convex edges of the triangulation that optimum gives (all factors). */
  value: number;
  /** relaxed + the largest value of each cut factor: at least the optimum. */
  bound: number;
  choice: Uint8Array;
  width: number;
}

/** Span of each factor over the layers: [lowest, highest] layer of its quads. */
export function factorSpans(g: FactorGraph, layer: Int32Array): [number, number][] {
  return g.factors.map((f) => {
    let lo = Infinity, hi = -Infinity;
    for (const v of f.scope) (lo = Math.min(lo, layer[v]!)), (hi = Math.max(hi, layer[v]!));
    return [lo, hi];
  });
}

/** lambda = ceil(span / epsilon), span the widest factor (1 when the quads of a
 * factor are at most one layer apart: the paper's ceil(1 / epsilon)). */
export function bakerLambda(g: FactorGraph, layer: Int32Array, epsilon: number): number {
  let span = 1;
  for (const [lo, hi] of factorSpans(g, layer)) span = Math.max(span, hi - lo);
  return Math.max(1, Math.ceil(span / epsilon - 1e-9));
}

/** Does the cut of this shift (after the layers l with l mod lambda == shift)
 * separate a factor spanning layers lo..hi? */
export function isCut(lo: number, hi: number, shift: number, lambda: number): boolean {
  const firstCut = lo + ((((shift - lo) % lambda) + lambda) % lambda);
  return firstCut < hi;
}

export function bakerShift(g: FactorGraph, layer: Int32Array, lambda: number, shift: number): BakerShift {
  const spans = factorSpans(g, layer);
  const dropped: number[] = [];
  const kept: number[] = [];
  let droppedTop = 0;
  spans.forEach(([lo, hi], k) => {
    if (isCut(lo, hi, shift, lambda)) {
      dropped.push(k);
      droppedTop += Math.max(...g.factors[k]!.table);
    } else kept.push(k);
  });
  const r = maxSum(g, kept);
  return { shift, dropped, relaxed: r.value, value: evaluateFactors(g, r.choice), bound: r.value + droppedTop, choice: r.choice, width: r.width };
}
