// The paper's Section 2.1 in TypeScript, for display: the bottleneck model of a
// min-max pair objective (the value of every pair of adjacent triangles as a
// function of the quads that decide it) and, for one threshold, its eliminations
// and its 2-SAT instance. The library's solve(..., { trace: true }) says which
// thresholds its binary search tested; this module shows what each test saw.
import type { ObjectiveId } from 'hodt';
import { areaRatio, enclosingCircle, normalAngle } from './geometry.ts';
import type { QuadStructure, Tri } from './structure.ts';
import { solveTwoSat, type TwoSatResult } from './twoSat.ts';

export const PAIR_OBJECTIVES = [
  'minmax-edge-area-ratio',
  'minmax-edge-normal-angle',
  'minmax-edge-enclosing-circle',
  'minmax-vertex-area-ratio',
  'minmax-vertex-normal-angle',
] as const satisfies readonly ObjectiveId[];
export type PairObjective = (typeof PAIR_OBJECTIVES)[number];
export const isPairObjective = (id: string): id is PairObjective => (PAIR_OBJECTIVES as readonly string[]).includes(id);

/** Where a pair is, to draw it: an edge between two triangles, a quad's own
 * diagonal (its two triangles), or the triangles around a vertex. */
export type Source = { kind: 'edge'; u: number; v: number } | { kind: 'quad'; q: number } | { kind: 'vertex'; v: number };

/** A term: unary (r = -1, values for q's states 0 and 1 in v[0], v[1]) or binary
 * (v[x + 2y] for q in state x and r in state y; q < r). */
export interface Term {
  q: number;
  r: number;
  v: [number, number, number, number];
  sources: Source[];
}

export interface PairModel {
  objective: PairObjective;
  /** Largest value among pairs of fixed triangles: no choice goes below it. */
  floor: number;
  floorSources: { source: Source; value: number }[];
  terms: Term[];
  /** The candidate values of the optimum, ascending (as the core sorts them). */
  candidates: number[];
}

type Measure = (p: Float64Array, s: Tri, t: Tri) => number;
const MEASURES: Record<PairObjective, Measure> = {
  'minmax-edge-area-ratio': areaRatio,
  'minmax-edge-normal-angle': normalAngle,
  'minmax-edge-enclosing-circle': enclosingCircle,
  'minmax-vertex-area-ratio': areaRatio,
  'minmax-vertex-normal-angle': normalAngle,
};

class Builder {
  floor = 0;
  floorSources: { source: Source; value: number }[] = [];
  terms: Term[] = [];
  unary = new Map<number, Term>();
  binary = new Map<number, Term>();
  constant(value: number, source: Source) {
    this.floor = Math.max(this.floor, value);
    this.floorSources.push({ source, value });
  }
  addUnary(q: number, v0: number, v1: number, source: Source) {
    const t = this.unary.get(q);
    if (!t) {
      const term: Term = { q, r: -1, v: [v0, v1, v0, v1], sources: [source] };
      this.unary.set(q, term);
      this.terms.push(term);
      return;
    }
    t.v[0] = t.v[2] = Math.max(t.v[0], v0);
    t.v[1] = t.v[3] = Math.max(t.v[1], v1);
    t.sources.push(source);
  }
  addBinary(q: number, r: number, v: [number, number, number, number], source: Source) {
    if (q > r) {
      [q, r] = [r, q];
      v = [v[0], v[2], v[1], v[3]];
    }
    const key = q * 0x100000 + r;
    const t = this.binary.get(key);
    if (!t) {
      const term: Term = { q, r, v: [...v], sources: [source] };
      this.binary.set(key, term);
      this.terms.push(term);
      return;
    }
    for (let k = 0; k < 4; k++) t.v[k] = Math.max(t.v[k]!, v[k]!);
    t.sources.push(source);
  }
}

export function buildPairModel(s: QuadStructure, objective: PairObjective): PairModel {
  const measure = MEASURES[objective];
  const p = s.points;
  const b = new Builder();
  const quadTriangles = (q: number, x: number): [Tri, Tri] => {
    const k1 = s.quadSlots[2 * q]!, k2 = s.quadSlots[2 * q + 1]!;
    const t = s.tri[x]!;
    return [
      [t[3 * k1]!, t[3 * k1 + 1]!, t[3 * k1 + 2]!],
      [t[3 * k2]!, t[3 * k2 + 1]!, t[3 * k2 + 2]!],
    ];
  };
  if (objective.startsWith('minmax-edge')) {
    for (let q = 0; q < s.m; q++) {
      const v0 = measure(p, ...quadTriangles(q, 0));
      const v1 = measure(p, ...quadTriangles(q, 1));
      b.addUnary(q, v0, v1, { kind: 'quad', q });
    }
    for (const e of s.skeleton) {
      const source: Source = { kind: 'edge', u: e.u, v: e.v };
      const { left: L, right: R } = e;
      if (L.quad < 0 && R.quad < 0) b.constant(measure(p, L.tri[0], R.tri[0]), source);
      else if (L.quad < 0 || R.quad < 0) {
        const Q = L.quad >= 0 ? L : R;
        const F = L.quad >= 0 ? R : L;
        b.addUnary(Q.quad, measure(p, Q.tri[0], F.tri[0]), measure(p, Q.tri[1], F.tri[0]), source);
      } else {
        const v: [number, number, number, number] = [0, 0, 0, 0];
        for (let x = 0; x < 2; x++) for (let y = 0; y < 2; y++) v[x + 2 * y] = measure(p, L.tri[x]!, R.tri[y]!);
        b.addBinary(L.quad, R.quad, v, source);
      }
    }
  } else {
    // Vertex-adjacent pairs: all pairs of triangles around each vertex.
    const n = p.length / 3;
    const fixedAt: Tri[][] = Array.from({ length: n }, () => []);
    for (let k = 0; k < s.slotQuad.length; k++) {
      if (s.slotQuad[k]! >= 0) continue;
      const t: Tri = [s.tri[0][3 * k]!, s.tri[0][3 * k + 1]!, s.tri[0][3 * k + 2]!];
      for (const v of t) fixedAt[v]!.push(t);
    }
    const quadsAt: number[][] = Array.from({ length: n }, () => []);
    for (let q = 0; q < s.m; q++) for (let j = 0; j < 4; j++) quadsAt[s.quads[4 * q + j]!]!.push(q);
    for (let v = 0; v < n; v++) {
      const source: Source = { kind: 'vertex', v };
      const fixed = fixedAt[v]!;
      let floor = 0;
      for (let i = 0; i < fixed.length; i++) for (let j = i + 1; j < fixed.length; j++) floor = Math.max(floor, measure(p, fixed[i]!, fixed[j]!));
      b.constant(floor, source);
      const qs = quadsAt[v]!;
      const at = (q: number, x: number) => quadTriangles(q, x).filter((t) => t.includes(v));
      for (let i = 0; i < qs.length; i++) {
        const u: [number, number] = [0, 0];
        for (let x = 0; x < 2; x++) {
          const ti = at(qs[i]!, x);
          if (ti.length === 2) u[x] = Math.max(u[x]!, measure(p, ti[0]!, ti[1]!));
          for (const a of ti) for (const f of fixed) u[x] = Math.max(u[x]!, measure(p, a, f));
        }
        b.addUnary(qs[i]!, u[0], u[1], source);
        for (let j = i + 1; j < qs.length; j++) {
          const w: [number, number, number, number] = [0, 0, 0, 0];
          for (let x = 0; x < 2; x++) {
            for (let y = 0; y < 2; y++) {
              let worst = 0;
              for (const a of at(qs[i]!, x)) for (const c of at(qs[j]!, y)) worst = Math.max(worst, measure(p, a, c));
              w[x + 2 * y] = worst;
            }
          }
          b.addBinary(qs[i]!, qs[j]!, w, source);
        }
      }
    }
  }

  // Candidates: every term takes one of its values (lower bound), Delaunay
  // achieves the upper one; only values in between can be the optimum.
  let lower = b.floor, upper = b.floor;
  for (const t of b.terms) {
    const n = t.r < 0 ? 2 : 4;
    lower = Math.max(lower, Math.min(...t.v.slice(0, n)));
    upper = Math.max(upper, t.v[0]);
  }
  const set = new Set<number>([lower, upper]);
  for (const t of b.terms) for (let k = 0; k < (t.r < 0 ? 2 : 4); k++) if (t.v[k]! > lower && t.v[k]! < upper) set.add(t.v[k]!);
  const candidates = [...set].sort((a, c) => a - c);
  return { objective, floor: b.floor, floorSources: b.floorSources, terms: b.terms, candidates };
}

/** Over the threshold, allowing for the last bits in which this file's doubles may
 * differ from the core's (the thresholds are the core's own values). */
export function over(value: number, threshold: number): boolean {
  return value > threshold + 1e-9 * Math.max(1, Math.abs(threshold));
}

/** What the test "is there a first order triangulation with every pair at most t?"
 * sees, in the paper's order: fixed pairs over t answer no; a quad with both
 * states over t answers no; a quad with one state over t is forced; every
 * remaining pair over t between two quads becomes 2-SAT clauses. */
export interface StepAnalysis {
  threshold: number;
  immediateNo: boolean;
  /** Pairs of fixed triangles over t. */
  fixedOver: Source[];
  /** Quads with both states over t. */
  blocked: number[];
  /** Quads forced to one state: [quad, the state it must take]. */
  forced: [number, number][];
  /** Binary terms with some combination over t, and which combinations. */
  constraints: { term: Term; forbidden: [number, number][] }[];
  /** Clauses built (forced quads count one each), as the library counts them. */
  clauses: number;
  sat: TwoSatResult | null;
  satisfiable: boolean;
}

export function analyseStep(model: PairModel, m: number, threshold: number): StepAnalysis {
  const out: StepAnalysis = {
    threshold,
    immediateNo: false,
    fixedOver: model.floorSources.filter((f) => over(f.value, threshold)).map((f) => f.source),
    blocked: [],
    forced: [],
    constraints: [],
    clauses: 0,
    sat: null,
    satisfiable: false,
  };
  if (out.fixedOver.length > 0) out.immediateNo = true;
  const clauses: [number, number][] = [];
  for (const t of model.terms) {
    if (t.r < 0) {
      const o0 = over(t.v[0], threshold), o1 = over(t.v[1], threshold);
      if (o0 && o1) out.blocked.push(t.q);
      else if (o0 || o1) {
        const keep = o1 ? 0 : 1;
        out.forced.push([t.q, keep]);
        clauses.push([2 * t.q + keep, 2 * t.q + keep]);
      }
      continue;
    }
    const forbidden: [number, number][] = [];
    for (let x = 0; x < 2; x++) {
      for (let y = 0; y < 2; y++) {
        if (!over(t.v[x + 2 * y]!, threshold)) continue;
        forbidden.push([x, y]);
        clauses.push([2 * t.q + (1 - x), 2 * t.r + (1 - y)]);
      }
    }
    if (forbidden.length) out.constraints.push({ term: t, forbidden });
  }
  if (out.blocked.length > 0) out.immediateNo = true;
  if (out.immediateNo) return out; // the library stops here (no clauses counted)
  out.clauses = clauses.length;
  out.sat = solveTwoSat(m, clauses);
  out.satisfiable = out.sat.satisfiable;
  return out;
}
