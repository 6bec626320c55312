// The NP-hardness construction of Section 3.1 (fewest mixed vertices), built from
// a small 3-SAT formula, with coordinates and heights of our own:
//
// - a variable is a fan (the paper's Figure 3) on a cell of a hexagonal grid: a
//   centre, an inner ring of 6 points at radius INNER and the cell's 6 corners as
//   the outer ring, so the 6 sectors between the rings are isosceles trapezoids,
//   cocircular, so flippable. Inner point k lies (almost) on the segment between
//   corners k - 1 and k + 1, its two possible diagonal neighbours (the paper's
//   dotted edges): sector k - 1 reaches it with its clockwise diagonal, sector k
//   with its counterclockwise one.
// - heights alternate around the rings: odd inner points at +L, even at -L, odd
//   corners at -2L, even at +2L, the centre at 0 (the grid's corners split into
//   the same two classes in every cell, so neighbouring cells agree). An odd inner
//   point is then far above its fixed neighbours and the segment between its two
//   diagonal neighbours passes above it: it is mixed exactly when both diagonals
//   are there (Observation 1); an even one is the same upside down. So a fan is
//   free of mixed inner points only when all 6 sectors turn the same way,
//   clockwise or counterclockwise: the variable's two values (which one means
//   "true" is chosen per fan). The centre, with neighbours alternately above and
//   below, is always mixed (a grey vertex); a corner, far above or below all its
//   neighbours, never is (a white one).
// - in a fan's pure state each of its corners has exactly one diagonal neighbour
//   from it: the inner point before it (counterclockwise) or after it
//   (clockwise). A clause is a corner where the fans of its variables meet (the
//   paper's Figure 5): three cells around one grid corner for three literals, two
//   cells sharing a side for two, one cell for one. The clause vertex is moved
//   from ±2L to ±CLAUSE_Z·L; the diagonal neighbour of each literal's false state
//   stays at ±L, above it, and that of the true state drops to ±TRUE_Z·L, below
//   it. The false ones are laid out around the vertex so that, all present, every
//   plane through it has one above (three points around it, or two on a line
//   through it), and any one of them replaced by a true one leaves a plane with
//   every neighbour below: the vertex is mixed exactly when every literal is
//   false (Observation 2). For one literal, an extra point beyond the vertex, on
//   the line from the false neighbour and at the vertex's height, plays the part
//   of the missing literals.
// - the empty cells next to a fan are filled with two centre points at 0 and the
//   cell's corners at ±2L: their centres are always mixed too.
//
// So the number of mixed vertices is at least the number of centres, and reaches
// it exactly when every fan is in a pure state and no clause vertex is mixed:
// exactly when the formula is satisfiable. The paper splits and bends fan chains
// to reach any planar 3-SAT formula; here each variable is a single fan, so the
// formula must fit on the grid: the fans of each clause meet at a corner, one
// corner per clause (found by search, or refused with the reason). Whether an
// instance behaves as claimed is checked by the view with the exact solver
// (check.ts).
import type { Cnf, Literal } from '../formula.ts';
import { clauseText } from '../chainLayout.ts';

/** Height scale (any positive value gives the same classes). */
const L = 10;
const SECTORS = 6;
/** Cell circumradius (the outer ring). */
const R = 2;
/** Inner ring radius: a little inside the chords between every other corner
 * (R / 2), so that a sector's circle does not pass through the inner points of
 * the cell across its outer side. */
const INNER = 0.96;
/** The centre is two points this far either side of the cell's middle: with two
 * points inside the inner ring's circle, no triangle of three inner points (or
 * three corners of a filled cell) is first order, so those triangles are fixed. */
const CENTRE_SPLIT = 0.3;
/** Clause vertex height, and the true-state neighbours' height, in units of L
 * (the false ones stay at 1): CLAUSE_Z < 1 puts the false neighbours above the
 * vertex; TRUE_Z < 2 * CLAUSE_Z - 1 puts a true neighbour lower below the vertex
 * than a false one is above it, so that a false and a true one on a line through
 * the vertex leave it a plane; TRUE_Z > 0 keeps a lowered inner point above its
 * fan's centre. */
const CLAUSE_Z = 0.8;
const TRUE_Z = 0.3;
/** How far beyond a one-literal clause vertex its extra point is. */
const UNIT_REACH = 0.6;

export class MixedLayoutError extends Error {
  override name = 'MixedLayoutError';
}

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
   * point k to corner k + 1) means "true". */
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
  /** Mixed vertices every triangulation has (the centres of fans and filled
   * cells), so the proof's prediction: this many when the formula is
   * satisfiable, more when not. */
  floor: number;
  /** The grid cell (axial q, r) of each variable's fan. */
  cells: [number, number][];
}

/** Sector k of a fan: inner k, corner k, corner k + 1, inner k + 1; its
 * counterclockwise diagonal is inner k to corner k + 1. */
export const sectorCorners = (fan: Fan, k: number): [number, number, number, number] => {
  const n = fan.inner.length;
  return [fan.inner[k]!, fan.outer[k]!, fan.outer[(k + 1) % n]!, fan.inner[(k + 1) % n]!];
};

// The grid: flat-topped hexagons in axial coordinates; corner k of a cell is at
// angle 60k degrees from its centre.
type Cell = [number, number];
const centreOf = ([q, r]: Cell): [number, number] => [1.5 * R * q, Math.sqrt(3) * R * (r + q / 2)];
const cornerOf = (c: Cell, k: number): [number, number] => {
  const [x, y] = centreOf(c);
  const a = (((k % 6) + 6) % 6) * (Math.PI / 3);
  return [x + R * Math.cos(a), y + R * Math.sin(a)];
};
const innerOf = (c: Cell, k: number): [number, number] => {
  const [x, y] = centreOf(c);
  const a = (((k % 6) + 6) % 6) * (Math.PI / 3);
  return [x + INNER * Math.cos(a), y + INNER * Math.sin(a)];
};
const NEIGHBOUR_DIRS: Cell[] = [[1, 0], [0, 1], [-1, 1], [-1, 0], [0, -1], [1, -1]];
/** The cells around corner k of cell c (c first), each with its index of that corner. */
const aroundCorner = (c: Cell, k: number): [Cell, number][] => {
  const [x, y] = cornerOf(c, k);
  const out: [Cell, number][] = [[c, ((k % 6) + 6) % 6]];
  for (const [dq, dr] of NEIGHBOUR_DIRS) {
    const d: Cell = [c[0] + dq, c[1] + dr];
    for (let j = 0; j < 6; j++) {
      const [u, v] = cornerOf(d, j);
      if (Math.hypot(u - x, v - y) < 1e-6) out.push([d, j]);
    }
  }
  return out;
};
const cellKey = ([q, r]: Cell) => `${q},${r}`;
const adjacent = (a: Cell, b: Cell) => NEIGHBOUR_DIRS.some(([dq, dr]) => a[0] + dq === b[0] && a[1] + dr === b[1]);

/** Where a clause sits: per literal, its variable and that fan's index of the
 * clause's corner; `key` is the corner's position. */
interface ClauseSite {
  clause: number;
  at: { variable: number; literal: Literal; k: number }[];
  key: string;
}

/** Inner point indices of corner k's two diagonal neighbours in a fan: the
 * counterclockwise state's (inner k - 1) and the clockwise state's (inner k + 1). */
const candidates = (k: number) => ({ ccw: (k + 5) % 6, cw: (k + 1) % 6 });

/** Does the clause vertex behave with these false neighbours (as seen from it)?
 * Three: about 120 degrees apart, so all three leave no plane with them below
 * and any two do (two nearly opposite ones alone would make it mixed); two:
 * nearly opposite, on a line through it. */
function falseNeighboursFit(z: [number, number], pts: [number, number][]): boolean {
  const angle = (a: [number, number], b: [number, number]) => {
    const u = [a[0] - z[0], a[1] - z[1]], v = [b[0] - z[0], b[1] - z[1]];
    return Math.acos((u[0]! * v[0]! + u[1]! * v[1]!) / (Math.hypot(u[0]!, u[1]!) * Math.hypot(v[0]!, v[1]!))) * (180 / Math.PI);
  };
  if (pts.length === 3) {
    const [a, b, c] = pts as [[number, number], [number, number], [number, number]];
    return [angle(a, b), angle(b, c), angle(c, a)].every((t) => t > 100 && t < 140);
  }
  if (pts.length === 2) return angle(pts[0]!, pts[1]!) > 170;
  return true;
}

interface Plan {
  cells: Cell[];
  ccwIsTrue: boolean[];
  sites: ClauseSite[];
}

/** The level each inner point next to a clause vertex must have ("false": stays
 * at ±L; "true": drops to ±TRUE_Z·L), or the reason no levels fit. */
function planHeights(f: Cnf, plan: Plan): { inner: Map<string, 'false' | 'true'>; reason: string | null } {
  const inner = new Map<string, 'false' | 'true'>();
  const want = (cell: Cell, i: number, level: 'false' | 'true'): string | null => {
    const key = `${cellKey(cell)}:${i}`;
    const had = inner.get(key);
    if (had && had !== level) return 'two clauses want one point at different heights';
    inner.set(key, level);
    return null;
  };
  const cellOfVar = (v: number) => plan.cells[v]!;
  const occupied = new Map<string, number>();
  plan.cells.forEach((c, v) => c && occupied.set(cellKey(c), v));
  for (const site of plan.sites) {
    const first = site.at[0]!;
    for (const [cell, k] of aroundCorner(cellOfVar(first.variable), first.k)) {
      const v = occupied.get(cellKey(cell));
      if (v === undefined) continue;
      const mine = site.at.find((a) => a.variable === v);
      const { ccw, cw } = candidates(k);
      if (!mine) {
        // A fan not in the clause: neither of its diagonal neighbours may lift the vertex.
        const e = want(cell, ccw, 'true') ?? want(cell, cw, 'true');
        if (e) return { inner, reason: e };
        continue;
      }
      const falseIsCcw = plan.ccwIsTrue[v] === mine.literal.negated;
      const e = want(cell, falseIsCcw ? ccw : cw, 'false') ?? want(cell, falseIsCcw ? cw : ccw, 'true');
      if (e) return { inner, reason: e };
    }
  }
  // An inner point between two clause vertices (corners k - 1 and k + 1 both
  // lowered) must drop below them to keep its segment above it.
  const clauseCorners = new Set(plan.sites.map((s) => s.key));
  for (let v = 0; v < plan.cells.length; v++) {
    const c = cellOfVar(v);
    if (!c) continue;
    for (let i = 0; i < SECTORS; i++) {
      const a = cornerKey(c, i - 1), b = cornerKey(c, i + 1);
      if (clauseCorners.has(a) && clauseCorners.has(b)) {
        const e = want(c, i, 'true');
        if (e) return { inner, reason: 'a fan point between two clause vertices would have to be both above and below them' };
      }
    }
  }
  return { inner, reason: null };
}

const cornerKey = (c: Cell, k: number) => {
  const [x, y] = cornerOf(c, k);
  return positionKey(x, y);
};
/** One key per plane position (the grid's corners are computed from several cells). */
const positionKey = (x: number, y: number) => `${Math.round(x * 1e6)},${Math.round(y * 1e6)}`;

/** Corner index in each fan of the corner shared by the given cells (all
 * pairwise adjacent), or null. */
function sharedCorner(cells: Cell[]): number[] | null {
  const first = cells[0]!;
  for (let k = 0; k < SECTORS; k++) {
    const around = aroundCorner(first, k);
    const ks = cells.map((c) => around.find(([cell]) => cellKey(cell) === cellKey(c))?.[1]);
    if (ks.every((x) => x !== undefined)) return ks as number[];
  }
  return null;
}

/** Candidate corners for each clause given the cells (units: any corner whose
 * other two cells are empty). */
function clauseOptions(f: Cnf, cells: Cell[], clauses: number[]): { variable: number; literal: Literal; k: number }[][][] {
  const occupied = new Set(cells.filter((c) => c !== undefined).map(cellKey));
  return clauses.map((k) => {
    const c = f.clauses[k]!;
    const cs = c.map((l) => cells[l.variable]!);
    const options: { variable: number; literal: Literal; k: number }[][] = [];
    if (c.length === 1) {
      for (let k = 0; k < SECTORS; k++) {
        const around = aroundCorner(cs[0]!, k);
        if (around.slice(1).some(([cell]) => occupied.has(cellKey(cell)))) continue;
        options.push([{ variable: c[0]!.variable, literal: c[0]!, k }]);
      }
      return options;
    }
    // Two or three cells around one corner (two cells share two corners).
    const first = cs[0]!;
    for (let k = 0; k < SECTORS; k++) {
      const around = aroundCorner(first, k);
      const ks = cs.map((cell) => around.find(([a]) => cellKey(a) === cellKey(cell))?.[1]);
      if (ks.every((x) => x !== undefined)) options.push(c.map((l, i) => ({ variable: l.variable, literal: l, k: ks[i]! })));
    }
    return options;
  });
}

/** Geometric check of a clause at a corner under given polarities. */
function siteWorks(cells: Cell[], ccwIsTrue: boolean[], at: { variable: number; literal: Literal; k: number }[]): boolean {
  const z = cornerOf(cells[at[0]!.variable]!, at[0]!.k);
  const falses = at.map((a) => {
    const falseIsCcw = ccwIsTrue[a.variable] === a.literal.negated;
    const { ccw, cw } = candidates(a.k);
    return innerOf(cells[a.variable]!, falseIsCcw ? ccw : cw);
  });
  return falseNeighboursFit(z, falses);
}

/**
 * Which state of each fan means "true". At a corner where three fans meet their
 * counterclockwise neighbours are 120 degrees apart (so are the clockwise ones),
 * so a three-literal clause needs its literals' false states to turn the same
 * way; two fans sharing a side meet at its two ends, and at each end one fan's
 * counterclockwise neighbour is opposite the other's clockwise one, so a
 * two-literal clause needs them to turn opposite ways. These are parity
 * constraints between the fans' polarities: solved by union-find, up to one flip
 * per connected part of the formula, or refused with the clause that closes an
 * odd cycle.
 */
function polarities(f: Cnf): { ccwIsTrue: boolean[]; part: number[] } {
  const n = f.names.length;
  const parent = Array.from({ length: n }, (_, v) => v);
  const parity = new Array<number>(n).fill(0); // p_v = p_root ^ parity[v]
  const find = (v: number): number => {
    if (parent[v] === v) return v;
    const up = parent[v]!;
    const root = find(up);
    parity[v] = parity[v]! ^ parity[up]!;
    parent[v] = root;
    return root;
  };
  f.clauses.forEach((c) => {
    for (let i = 1; i < c.length; i++) {
      const a = c[0]!, b = c[i]!;
      // p_a ^ p_b must be neg_a ^ neg_b (same way) or its negation (opposite ways).
      const want = (a.negated ? 1 : 0) ^ (b.negated ? 1 : 0) ^ (c.length === 2 ? 1 : 0);
      const ra = find(a.variable), rb = find(b.variable);
      if (ra === rb) {
        if ((parity[a.variable]! ^ parity[b.variable]!) !== want) {
          throw new MixedLayoutError(
            `${clauseText(f, c)} closes a cycle of clauses that asks a fan to turn both ways at once (a three-literal clause needs its false literals' fans to turn the same way, a two-literal one opposite ways; the paper fixes this with inverter gadgets, which this page does not build)`,
          );
        }
      } else {
        parent[ra] = rb;
        parity[ra] = parity[a.variable]! ^ parity[b.variable]! ^ want;
      }
    }
  });
  const ccwIsTrue = Array.from({ length: n }, (_, v) => (find(v), parity[v] === 1));
  return { ccwIsTrue, part: Array.from({ length: n }, (_, v) => find(v)) };
}

/** Give up a layout search after this many steps (placements and corner
 * choices), so that the page answers within a second whatever is typed. */
const SEARCH_LIMIT = 200000;

/** Find cells, polarities and clause corners for the formula, or say why not:
 * each connected part of the formula is placed on its own, its variables one by
 * one next to an already placed clause neighbour, then the parts side by side. */
function findPlan(f: Cnf): Plan {
  const n = f.names.length;
  const pol = polarities(f);
  const parts = [...new Set(pol.part)].map((root) => pol.part.map((r, v) => (r === root ? v : -1)).filter((v) => v >= 0));
  const neighbours: Set<number>[] = Array.from({ length: n }, () => new Set());
  f.clauses.forEach((c) => c.forEach((a) => c.forEach((b) => a.variable !== b.variable && neighbours[a.variable]!.add(b.variable))));
  const cells: Cell[] = new Array(n);
  const ccwIsTrue = pol.ccwIsTrue.slice();
  const sites: ClauseSite[] = [];
  let why = '';
  const budget = { steps: 0 };
  let shiftQ = 0;
  for (const part of parts) {
    // Breadth-first order: every variable after the first has a placed clause neighbour.
    const order = [part[0]!];
    for (let i = 0; i < order.length; i++) for (const w of neighbours[order[i]!]!) if (!order.includes(w)) order.push(w);
    const clausesHere = f.clauses.map((c, k) => k).filter((k) => part.includes(f.clauses[k]![0]!.variable));
    const placedAt = new Map<string, number>();
    let found: ClauseSite[] | null = null;
    const clausesDoneBy = (i: number) => clausesHere.filter((k) => f.clauses[k]!.every((l) => order.indexOf(l.variable) <= i) && f.clauses[k]!.some((l) => l.variable === order[i]));
    const place = (i: number): boolean => {
      if (i === order.length) {
        for (const flip of [false, true]) {
          for (const v of part) ccwIsTrue[v] = pol.ccwIsTrue[v] !== flip;
          const local = cells.map((c, w) => (part.includes(w) ? c : undefined)) as Cell[];
          const got = chooseCorners(f, local, ccwIsTrue, clausesHere, budget, (reason) => (why = reason));
          if (got) {
            found = got;
            return true;
          }
        }
        return false;
      }
      if (++budget.steps > SEARCH_LIMIT) return false;
      const v = order[i]!;
      const near = order.slice(0, i).find((w) => neighbours[v]!.has(w));
      const options: Cell[] = near === undefined ? [[0, 0]] : NEIGHBOUR_DIRS.map(([dq, dr]) => [cells[near]![0] + dq, cells[near]![1] + dr] as Cell);
      for (const cell of options) {
        if (placedAt.has(cellKey(cell))) continue;
        cells[v] = cell;
        const ok = clausesDoneBy(i).every((k) => {
          const cs = f.clauses[k]!.map((l) => cells[l.variable]!);
          for (let a = 0; a < cs.length; a++) for (let b = a + 1; b < cs.length; b++) if (!adjacent(cs[a]!, cs[b]!)) return false;
          return cs.length < 3 || sharedCorner(cs) !== null;
        });
        if (!ok) continue;
        placedAt.set(cellKey(cell), v);
        if (place(i + 1)) return true;
        placedAt.delete(cellKey(cell));
      }
      return false;
    };
    if (!place(0) || !found) {
      if (budget.steps > SEARCH_LIMIT) throw new MixedLayoutError('the search for a layout on the grid gave up: try a smaller formula');
      throw new MixedLayoutError(`this formula does not fit the grid of single fans: ${why || 'the fans of its clauses cannot all meet at corners (three fans around each three-literal clause\'s corner, two sharing a side for a two-literal one)'}`);
    }
    // Move this part right of the previous ones (an even shift of q, with r
    // shifted back by half, moves cells straight along x), with two empty cells between.
    const minQ = Math.min(...part.map((v) => cells[v]![0]));
    const dq = shiftQ - minQ + ((shiftQ - minQ) % 2 === 0 ? 0 : 1);
    for (const v of part) cells[v] = [cells[v]![0] + dq, cells[v]![1] - dq / 2];
    shiftQ = Math.max(...part.map((v) => cells[v]![0])) + 4;
    for (const site of found as ClauseSite[]) sites.push({ ...site, key: cornerKey(cells[site.at[0]!.variable]!, site.at[0]!.k) });
  }
  return { cells, ccwIsTrue, sites };
}

/** A corner per clause (distinct, with its false neighbours around it, heights
 * consistent), or null with the reason given to `fail`. */
function chooseCorners(f: Cnf, cells: Cell[], ccwIsTrue: boolean[], clauses: number[], budget: { steps: number }, fail: (why: string) => void): ClauseSite[] | null {
  const options = clauseOptions(f, cells, clauses);
  const sites: ClauseSite[] = [];
  const taken = new Set<string>();
  let noUnitRoom = false;
  const choose = (i: number): boolean => {
    if (++budget.steps > SEARCH_LIMIT) return false;
    if (i === clauses.length) {
      const { reason } = planHeights(f, { cells, ccwIsTrue, sites });
      if (reason) fail(reason);
      return reason === null;
    }
    const k = clauses[i]!;
    if (options[i]!.length === 0) noUnitRoom = true;
    for (const at of options[i]!) {
      const key = cornerKey(cells[at[0]!.variable]!, at[0]!.k);
      if (taken.has(key) || !siteWorks(cells, ccwIsTrue, at)) continue;
      taken.add(key);
      sites.push({ clause: k, at, key });
      if (choose(i + 1)) return true;
      sites.pop();
      taken.delete(key);
    }
    return false;
  };
  if (choose(0)) return sites.slice();
  if (noUnitRoom) fail('a one-literal clause needs a corner of its fan that no other fan touches');
  return null;
}

export function buildMixedGadget(f: Cnf): MixedGadget {
  const occurrences = new Array<number>(f.names.length).fill(0);
  f.clauses.forEach((c) => c.forEach((l) => occurrences[l.variable]!++));
  occurrences.forEach((o, v) => {
    if (o > SECTORS) throw new MixedLayoutError(`${f.names[v]} is in ${o} clauses: a fan has ${SECTORS} corners`);
  });
  f.clauses.forEach((c, k) =>
    f.clauses.forEach((d, j) => {
      if (j > k && c.length === 3 && d.length === 3 && c.every((l) => d.some((m) => m.variable === l.variable))) {
        throw new MixedLayoutError(`${clauseText(f, c)} and ${clauseText(f, d)} have the same three variables, and three fans meet at one corner only`);
      }
    }),
  );
  const plan = findPlan(f);
  const { inner: levels } = planHeights(f, plan);
  const xs: number[] = [], ys: number[] = [], zs: number[] = [];
  const roles: MixedRole[] = [];
  const index = new Map<string, number>();
  const point = (x: number, y: number, z: number, role: MixedRole) => {
    const key = positionKey(x, y);
    const i = index.get(key);
    if (i !== undefined) return i;
    index.set(key, xs.length);
    xs.push(x), ys.push(y), zs.push(z), roles.push(role);
    return xs.length - 1;
  };
  const cornerHeight = (k: number) => (k % 2 ? -2 * L : 2 * L);
  const fans: Fan[] = plan.cells.map((cell, variable) => {
    const [cx, cy] = centreOf(cell);
    const fan: Fan = { variable, x: cx, y: cy, centre: point(cx - CENTRE_SPLIT, cy, 0, 'centre'), inner: [], outer: [], ccwIsTrue: plan.ccwIsTrue[variable]! };
    point(cx + CENTRE_SPLIT, cy, 0, 'centre');
    for (let k = 0; k < SECTORS; k++) {
      const [x, y] = innerOf(cell, k);
      const level = levels.get(`${cellKey(cell)}:${k}`);
      const sign = k % 2 ? 1 : -1;
      fan.inner.push(point(x, y, sign * (level === 'true' ? TRUE_Z : 1) * L, 'inner'));
    }
    for (let k = 0; k < SECTORS; k++) {
      const [x, y] = cornerOf(cell, k);
      fan.outer.push(point(x, y, cornerHeight(k), 'outer'));
    }
    return fan;
  });
  // Filled cells: every empty cell next to a fan.
  const occupied = new Set(plan.cells.map(cellKey));
  const filled = new Map<string, Cell>();
  for (const c of plan.cells) for (const [dq, dr] of NEIGHBOUR_DIRS) {
    const e: Cell = [c[0] + dq, c[1] + dr];
    if (!occupied.has(cellKey(e))) filled.set(cellKey(e), e);
  }
  for (const cell of filled.values()) {
    const [cx, cy] = centreOf(cell);
    point(cx - CENTRE_SPLIT, cy, 0, 'centre');
    point(cx + CENTRE_SPLIT, cy, 0, 'centre');
    for (let k = 0; k < SECTORS; k++) {
      const [x, y] = cornerOf(cell, k);
      point(x, y, cornerHeight(k), 'fill');
    }
  }
  const clauses: MixedClauseVertex[] = [];
  for (const site of plan.sites) {
    const first = site.at[0]!;
    const fan0 = fans[first.variable]!;
    const z = fan0.outer[first.k]!;
    const sign = first.k % 2 ? -1 : 1;
    zs[z] = sign * CLAUSE_Z * L;
    const partners = site.at.map((a) => {
      const fan = fans[a.variable]!;
      const { ccw, cw } = candidates(a.k);
      return fan.inner[fan.ccwIsTrue === a.literal.negated ? ccw : cw]!;
    });
    if (site.at.length === 1) {
      roles[z] = 'unit';
      const p = partners[0]!;
      const dx = xs[z]! - xs[p]!, dy = ys[z]! - ys[p]!, len = Math.hypot(dx, dy);
      point(xs[z]! + (UNIT_REACH * dx) / len, ys[z]! + (UNIT_REACH * dy) / len, zs[z]!, 'fill');
    } else roles[z] = 'clause';
    clauses.push({ clause: site.clause, point: z, literals: f.clauses[site.clause]!, partners });
  }
  const points = new Float64Array(3 * xs.length);
  xs.forEach((x, i) => {
    points[3 * i] = x;
    points[3 * i + 1] = ys[i]!;
    points[3 * i + 2] = zs[i]!;
  });
  clauses.sort((a, b) => a.clause - b.clause);
  return { formula: f, points, fans, clauses, roles, floor: roles.filter((r) => r === 'centre').length, cells: plan.cells };
}
