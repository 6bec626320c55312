// The NP-hardness construction of Section 3.1 (fewest mixed vertices), built from
// a small formula, with coordinates and heights of our own:
//
// - a variable is a fan (the paper's Figure 3): a centre, an inner ring of 8
//   points at radius 1 and an outer ring of 8 at radius √2, so the 8 sectors
//   between the rings are cocircular quads (flippable). Inner point k lies on the
//   segment between outer points k - 1 and k + 1, which are its two possible
//   diagonal neighbours (the paper's dotted edges): sector k - 1 reaches it with
//   its clockwise diagonal, sector k with its counterclockwise one.
// - heights alternate around the rings: odd inner points at +L, even at -L, odd
//   outer points at -2L, even at +2L, the centre at 0. An odd inner point is then
//   far above its fixed neighbours (centre, ring neighbours, the outer point
//   across), and the segment between its two diagonal neighbours (+2L) passes
//   above it: it is mixed exactly when both diagonals are there (Observation 1).
//   An even inner point is the same upside down. So a sector using its clockwise
//   diagonal followed by one using its counterclockwise one costs a mixed vertex,
//   and around the ring the only free states are all clockwise or all
//   counterclockwise: the variable's two values. The centre, with neighbours
//   alternately above and below, is always mixed (a grey vertex); the outer
//   points are always extrema (white ones).
// - a two-literal clause is a joint: the next fan of the chain shares the
//   first's east outer point Z (their west one). Z, at +L/2, has two pairs of
//   possible diagonal neighbours that lie on lines through it, one from each fan:
//   (first fan's inner 1, second's inner 5), present when both fans are clockwise,
//   and (first's 7, second's 3), present when both are counterclockwise. A pair
//   that carries a clause stays at +L, so Z is mixed when both are there, that
//   is when both literals are false (Observation 2 for two literals); a pair
//   without a clause is lowered to +L/4, under Z. Which state of a fan means
//   "true" is chosen per fan so that each clause's false literals are its pair.
//   Two clauses fit on one joint only if the second negates both literals of the
//   first (the other pair).
// - a one-literal clause is an even outer point at the top or bottom of its fan,
//   lowered to +L/2, with one extra point beyond it on the line from its
//   neighbour of the false state: it is mixed exactly when that diagonal is there.
// - the two points above and below each joint, low, close the gap between two
//   fans; chains follow each other along one line with a gap between them.
//
// So the number of mixed vertices is at least the number of fans (their centres),
// and reaches it exactly when every fan is in a pure state and no clause vertex is
// mixed: exactly when the formula is satisfiable. The layout takes the formulas
// the Section 3.2 gadget takes (chainLayout.ts): the paper's three-literal clause
// vertices and splitting fans are not built. Whether an instance behaves as
// claimed is checked by the view with the exact solver (mixedCheck.ts).
import type { Cnf, Literal } from './formula.ts';
import { chainLayout, ChainLayoutError, clauseText } from './chainLayout.ts';

/** Height scale (any positive value gives the same classes). */
const L = 10;
const SECTORS = 8;
const R_INNER = 1;
const R_OUTER = Math.SQRT2;
/** The centre is two points this far either side of the fan's middle: with two
 * points inside the inner ring's circle, no triangle of three inner points is
 * first order, so the triangles inside the ring are fixed. */
const CENTRE_SPLIT = 0.15;
/** Space between two chains, beyond the outer rings. */
const CHAIN_GAP = 1.5;
/** How far the points that close a joint's gap are above and below it. */
const JOINT_FILL = 1.3;
/** How far beyond a one-literal clause vertex its extra point is. */
const UNIT_REACH = 0.6;
/** A second, higher pair of low points over each joint keeps the extra points
 * of two neighbouring one-literal clauses from seeing each other's vertex. */
const JOINT_CAP = 2.3;

export type MixedRole = 'centre' | 'inner' | 'outer' | 'clause' | 'unit' | 'fill';

export interface Fan {
  variable: number;
  /** Centre (x, y). */
  x: number;
  y: number;
  centre: number;
  inner: number[];
  outer: number[];
  /** True when the counterclockwise state (every sector's diagonal from inner
   * point k to outer point k + 1) means "true". */
  ccwIsTrue: boolean;
}

export interface MixedClauseVertex {
  clause: number;
  point: number;
  literals: Literal[];
  /** The possible diagonal neighbours that are there when its literals are false. */
  partners: number[];
}

export interface MixedGadget {
  formula: Cnf;
  /** x, y, z per point. */
  points: Float64Array;
  fans: Fan[];
  clauses: MixedClauseVertex[];
  roles: MixedRole[];
  /** Mixed vertices every triangulation has (the fans' centres), so the proof's
   * prediction: this many when the formula is satisfiable, more when not. */
  floor: number;
  chains: number[][];
}

/** Sector k of a fan: inner k, outer k, outer k + 1, inner k + 1; its
 * counterclockwise diagonal is inner k to outer k + 1. */
export const sectorCorners = (fan: Fan, k: number): [number, number, number, number] => [fan.inner[k]!, fan.outer[k]!, fan.outer[(k + 1) % SECTORS]!, fan.inner[(k + 1) % SECTORS]!];

export function buildMixedGadget(f: Cnf): MixedGadget {
  const { chains, joints, units } = chainLayout(f);
  const xs: number[] = [], ys: number[] = [], zs: number[] = [];
  const roles: MixedRole[] = [];
  const index = new Map<string, number>();
  const point = (x: number, y: number, z: number, role: MixedRole) => {
    const key = `${x.toFixed(9)},${y.toFixed(9)}`;
    const i = index.get(key);
    if (i !== undefined) return i;
    index.set(key, xs.length);
    xs.push(x), ys.push(y), zs.push(z), roles.push(role);
    return xs.length - 1;
  };
  const fans: Fan[] = [];
  const fanOf = new Int32Array(f.names.length).fill(-1);
  const clauses: MixedClauseVertex[] = [];
  let x0 = 0;
  for (const chain of chains) {
    chain.forEach((variable, i) => {
      const cx = x0 + i * 2 * R_OUTER;
      const fan: Fan = { variable, x: cx, y: 0, centre: point(cx - CENTRE_SPLIT, 0, 0, 'centre'), inner: [], outer: [], ccwIsTrue: true };
      point(cx + CENTRE_SPLIT, 0, 0, 'centre');
      const angle = (k: number) => (k * 2 * Math.PI) / SECTORS;
      for (let k = 0; k < SECTORS; k++) fan.inner.push(point(cx + R_INNER * Math.cos(angle(k)), R_INNER * Math.sin(angle(k)), k % 2 ? L : -L, 'inner'));
      // (Outer 4 of every fan but a chain's first is the previous fan's outer 0.)
      for (let k = 0; k < SECTORS; k++) fan.outer.push(point(cx + R_OUTER * Math.cos(angle(k)), R_OUTER * Math.sin(angle(k)), k % 2 ? -2 * L : 2 * L, 'outer'));
      fanOf[variable] = fans.length;
      fans.push(fan);
      if (i === 0) return;
      const prev = fans[fans.length - 2]!;
      const z = prev.outer[0]!;
      zs[z] = L / 2;
      roles[z] = 'clause';
      // The pairs through Z: "cw" is there when both fans are clockwise.
      const pairs = { cw: [prev.inner[1]!, fan.inner[5]!], ccw: [prev.inner[7]!, fan.inner[3]!] };
      const used = new Set<'cw' | 'ccw'>();
      for (const k of joints.get(`${chain[i - 1]},${variable}`)!) {
        const lits = f.clauses[k]!;
        const theirs = lits.find((l) => l.variable !== variable)!, mine = lits.find((l) => l.variable === variable)!;
        // The previous fan's false literal: clockwise if its "true" is counterclockwise and the literal is positive, and so on.
        const prevFalseCw = prev.ccwIsTrue !== theirs.negated;
        const pair = prevFalseCw ? 'cw' : 'ccw';
        if (used.size === 0) fan.ccwIsTrue = (pair === 'cw') !== mine.negated;
        else if (used.has(pair) || fan.ccwIsTrue !== ((pair === 'cw') !== mine.negated)) {
          const [first] = joints.get(`${chain[i - 1]},${variable}`)!;
          throw new ChainLayoutError(`${clauseText(f, f.clauses[first!]!)} and ${clauseText(f, lits)} share two variables, and only clauses whose literals are each other's negations fit on the two pairs of one joint`);
        }
        used.add(pair);
        clauses.push({ clause: k, point: z, literals: lits, partners: pairs[pair] });
      }
      for (const pair of ['cw', 'ccw'] as const) if (!used.has(pair)) for (const p of pairs[pair]) zs[p] = L / 4;
    });
    x0 += (chain.length - 1) * 2 * R_OUTER + 2 * R_OUTER + CHAIN_GAP;
  }
  // Joint gaps: a low point above and below each shared outer point.
  for (const c of clauses) {
    if (roles[c.point] !== 'clause') continue;
    point(xs[c.point]!, JOINT_FILL, -2 * L, 'fill');
    point(xs[c.point]!, -JOINT_FILL, -2 * L, 'fill');
    point(xs[c.point]!, JOINT_CAP, -2 * L, 'fill');
    point(xs[c.point]!, -JOINT_CAP, -2 * L, 'fill');
  }
  // One-literal clauses: outer 2 (top) or 6 (bottom). At outer s, sector s - 1
  // reaches it from inner s - 1 counterclockwise, sector s from inner s + 1
  // clockwise. Pick the slot whose false-state neighbour no joint lowered.
  const free = new Set<number>();
  for (const fan of fans) free.add(fan.outer[2]!).add(fan.outer[6]!);
  units.forEach((occurrences, variable) => {
    for (const { clause, literal } of occurrences) {
      const fan = fans[fanOf[variable]!]!;
      const falseIsCcw = fan.ccwIsTrue === literal.negated;
      // An inner point between two lowered outer points (a clause vertex and
      // this one) at +L would lose its two diagonals' segment above it: refuse a
      // slot where that happens (the false-state neighbour needs +L).
      const squeezed = (inner: number, beyond: number) => zs[fan.inner[inner]!]! > L / 2 && (roles[fan.outer[beyond]!] === 'clause' || roles[fan.outer[beyond]!] === 'unit');
      const options = [2, 6].map((s) => ({ s, vertex: fan.outer[s]!, partner: fan.inner[falseIsCcw ? s - 1 : (s + 1) % SECTORS]! }));
      const pick = options.find((o) => free.has(o.vertex) && zs[o.partner] === L && !squeezed(o.s - 1, o.s - 2) && !squeezed(o.s + 1, (o.s + 2) % SECTORS));
      if (!pick) throw new ChainLayoutError(`no room for the one-literal clause ${clauseText(f, [literal])} on the fan of ${f.names[variable]}: its two free outer points each sit next to a clause pair of the joint (see the note below)`);
      free.delete(pick.vertex);
      const v = pick.vertex;
      zs[v] = L / 2;
      roles[v] = 'unit';
      const dx = xs[v]! - xs[pick.partner]!, dy = ys[v]! - ys[pick.partner]!, n = Math.hypot(dx, dy);
      point(xs[v]! + (UNIT_REACH * dx) / n, ys[v]! + (UNIT_REACH * dy) / n, L / 2, 'fill');
      clauses.push({ clause, point: v, literals: [literal], partners: [pick.partner] });
    }
  });
  const points = new Float64Array(3 * xs.length);
  xs.forEach((x, i) => {
    points[3 * i] = x;
    points[3 * i + 1] = ys[i]!;
    points[3 * i + 2] = zs[i]!;
  });
  clauses.sort((a, b) => a.clause - b.clause);
  return { formula: f, points, fans, clauses, roles, floor: roles.filter((r) => r === 'centre').length, chains };
}
