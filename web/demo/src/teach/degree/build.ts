// The NP-hardness construction of Section 3.2 (minimising the maximum degree),
// built from a small formula, with coordinates of our own:
//
// - a variable is a wire: a row of 1 x 0.8 rectangles (cells) sharing their short
//   sides. Every cell is a flippable quad (its corners are cocircular), so it adds
//   one diagonal, and so one to the degree of two opposite corners. A point on a
//   shared side has d - 1 fixed neighbours, so at most one of the two diagonals
//   that could reach it may be there: then every cell of the wire uses the same
//   diagonal (the paper's Figure 7), rising (south-west to north-east) or falling.
//   Which of the two means "true" is a per-wire polarity.
// - a clause of two literals is the side two wires share end to end: the corner
//   that the false literal's diagonal reaches is the same point on both sides, the
//   clause vertex, with d - 1 fixed neighbours, so the two literals cannot both be
//   false (the paper's clause vertex has d - k + 1 for k literals). Its other
//   corner has d - 2, so it takes both diagonals, or it is the vertex of a second
//   clause on the same two variables whose literals are the first one's negations.
// - a clause of one literal is a joint with a dummy cell (no variable) whose
//   corner has d fixed neighbours: no diagonal may reach it, so the literal is true.
// - chains follow each other along one line; where one ends and the next begins
//   they share a side whose corners have room for both diagonals.
// - fixed neighbours are the paper's Figure 9: a point just outside each cell's
//   circle above and below its middle, and beside each chain end; then, where a
//   point needs more, points on a circle through its two Figure 9 neighbours that
//   holds the point and the one across its cell (a flip of one of its edges would
//   make a triangle with three corners on that circle, which is not first order).
//
// - the domain maxEdge = 1.35 (DEFINITIONS.md, "Domain"): the long triangles that
//   fill the convex hull around the band are not measured. The paper fills the
//   holes with Ruppert's algorithm instead; without a domain, a point at the top
//   of the band can collect fill edges past d. This changes the measured problem,
//   and the page says so.
//
// So a triangulation of maximum degree at most d = 7 exists if and only if the
// formula is satisfiable. Wires are straight and have two ends, so the layout
// takes formulas whose clause graph is a set of chains: every variable in at most
// two clauses, clauses of one or two literals, no cycle (and no splitter or
// three-literal clause vertex, which the paper needs for 3-SAT). Whether the
// instance behaves as claimed is checked by the view with the exact solver
// (check.ts).
import type { Cnf, Literal } from '../formula.ts';
import { chainLayout, ChainLayoutError, clauseText } from '../chainLayout.ts';

export const DEGREE_BOUND = 7;
/** The domain the gadget is measured in: cell diagonals (1.28) and every edge
 * around a wire point are shorter, the triangles that fill the convex hull
 * around the band have a longer edge and are not measured. */
export const DEGREE_MAX_EDGE = 1.35;
const CELL = 1;
const WIDTH = 0.8;
const CELLS_PER_WIRE = 2;
/** How far outside a cell's circle its Figure 9 points are. */
const GAP = 0.03;

/** A formula the chain layout cannot take (chainLayout.ts). */
export { ChainLayoutError as DegreeLayoutError };

export interface DegreeCell {
  /** Lower-left corner. */
  x: number;
  y: number;
  /** Point indices: south-west, south-east, north-east, north-west. */
  corners: [number, number, number, number];
  /** The wire, or -1 for a one-literal clause's dummy cell. */
  wire: number;
  /** A dummy cell's clause corner, which its diagonal must avoid (else -1). */
  avoid: number;
}

export interface DegreeWire {
  variable: number;
  /** Cells from west to east. */
  cells: number[];
  /** True when the rising diagonal (south-west to north-east) means "true". */
  risingIsTrue: boolean;
}

export type VertexRole = 'wire' | 'clause' | 'unit' | 'slack' | 'end' | 'pendant';

export interface DegreeClauseVertex {
  clause: number;
  point: number;
  literals: Literal[];
}

export interface DegreeGadget {
  formula: Cnf;
  /** x, y, z per point (z = 0: degree does not depend on heights). */
  points: Float64Array;
  /** The points of the wires (the pendants come after them). */
  numWirePoints: number;
  cells: DegreeCell[];
  wires: DegreeWire[];
  clauses: DegreeClauseVertex[];
  /** Role of every point. */
  roles: VertexRole[];
  /** Fixed degree the construction gives each wire point (pendants excluded). */
  fixedDegree: number[];
  bound: number;
  /** The domain (Terrain.maxEdge) the reduction is stated in. */
  maxEdge: number;
  /** Variables of each chain, west to east. */
  chains: number[][];
}


export function buildDegreeGadget(f: Cnf): DegreeGadget {
  const { chains, joints, units } = chainLayout(f);
  const xs: number[] = [];
  const ys: number[] = [];
  const index = new Map<string, number>();
  const point = (x: number, y: number) => {
    const key = `${x.toFixed(6)},${y.toFixed(6)}`;
    let i = index.get(key);
    if (i === undefined) {
      i = xs.length;
      xs.push(x);
      ys.push(y);
      index.set(key, i);
    }
    return i;
  };
  const cells: DegreeCell[] = [];
  const wires: DegreeWire[] = [];
  const clauses: DegreeClauseVertex[] = [];
  const targets = new Map<number, number>();
  const roleOf = new Map<number, VertexRole>();
  const wireOf = new Int32Array(f.names.length).fill(-1);
  const north = new Set<number>();
  const extremes: [number, number][] = [];
  const acrossOf = (p: number) => index.get(`${xs[p]!.toFixed(6)},${(north.has(p) ? ys[p]! - WIDTH : ys[p]! + WIDTH).toFixed(6)}`)!;

  // The corner a false literal's diagonal reaches at one end of its wire: the
  // rising diagonal reaches the east end's north corner and the west end's south
  // corner, the falling one the other two.
  const cornerOf = (w: DegreeWire, literal: Literal, east: boolean): 'north' | 'south' => {
    const falseIsRising = w.risingIsTrue === literal.negated;
    return falseIsRising === east ? 'north' : 'south';
  };

  let next = 0;
  chains.forEach((chain) => {
    const y0 = 0;
    // Room for a dummy cell west of the chain when its first variable has a
    // one-literal clause (it goes to the west end).
    const start = next + (units[chain[0]!]!.length > 0 ? CELL : 0);
    let x0 = start;
    chain.forEach((variable, i) => {
      const w: DegreeWire = { variable, cells: [], risingIsTrue: true };
      const wire = wires.length;
      wires.push(w);
      wireOf[variable] = wire;
      for (let j = 0; j < CELLS_PER_WIRE; j++) {
        const x = x0 + j * CELL;
        const corners: [number, number, number, number] = [point(x, y0), point(x + CELL, y0), point(x + CELL, y0 + WIDTH), point(x, y0 + WIDTH)];
        north.add(corners[2]).add(corners[3]);
        w.cells.push(cells.length);
        cells.push({ x, y: y0, corners, wire, avoid: -1 });
      }
      // Inside a wire, the shared sides: d - 1 fixed neighbours.
      for (let j = 1; j < CELLS_PER_WIRE; j++) {
        for (const p of [point(x0 + j * CELL, y0), point(x0 + j * CELL, y0 + WIDTH)]) {
          targets.set(p, DEGREE_BOUND - 1);
          roleOf.set(p, 'wire');
        }
      }
      if (i > 0) {
        // The joint with the previous wire: its clause vertex is where the
        // previous wire's false literal reaches; this wire's polarity makes its
        // own false literal reach the same corner.
        const prevWire = wires[wire - 1]!;
        const [k, second] = joints.get(`${chain[i - 1]},${variable}`)!;
        const sides = (c: number) => {
          const lits = f.clauses[c]!;
          return [lits.find((l) => l.variable === variable)!, lits.find((l) => l.variable !== variable)!] as const;
        };
        const [mine, theirs] = sides(k!);
        const corner = cornerOf(prevWire, theirs, true);
        if (cornerOf(w, mine, false) !== corner) w.risingIsTrue = false;
        const at = (c: 'north' | 'south') => point(x0, c === 'north' ? y0 + WIDTH : y0);
        const other = corner === 'north' ? 'south' : 'north';
        const clauseAt = (c: number, where: 'north' | 'south') => {
          targets.set(at(where), DEGREE_BOUND - 1);
          roleOf.set(at(where), 'clause');
          clauses.push({ clause: c, point: at(where), literals: f.clauses[c]! });
        };
        clauseAt(k!, corner);
        if (second === undefined) roleOf.set(at(other), 'slack');
        else {
          const [mine2, theirs2] = sides(second);
          if (cornerOf(prevWire, theirs2, true) !== other || cornerOf(w, mine2, false) !== other) {
            throw new ChainLayoutError(`${clauseText(f, f.clauses[k!]!)} and ${clauseText(f, f.clauses[second]!)} share two variables, and only clauses whose literals are each other's negations fit on the two corners of one joint`);
          }
          clauseAt(second, other);
        }
      }
      x0 += CELLS_PER_WIRE * CELL;
    });
    // The chain's two ends: free, or a one-literal clause. A one-literal clause
    // is a joint with a dummy cell (no variable) whose corner there gets d fixed
    // neighbours: neither the false literal's diagonal nor the dummy's may reach
    // it, so the literal is true (and the dummy uses its other diagonal).
    const ends: [number, boolean][] = [[chain[0]!, false], [chain[chain.length - 1]!, true]];
    let first = cells.length - chain.length * CELLS_PER_WIRE, last = cells.length - 1;
    ends.forEach(([variable, east], e) => {
      if (chain.length === 1 && e === 1 && units[variable]!.length < 2) return;
      const unit = units[variable]![chain.length === 1 ? e : 0];
      if (!unit) return;
      const x = east ? x0 : start;
      const w = wires[wireOf[variable]!]!;
      const northCorner = point(x, y0 + WIDTH), southCorner = point(x, y0);
      const p = cornerOf(w, unit.literal, east) === 'north' ? northCorner : southCorner;
      targets.set(p, DEGREE_BOUND);
      roleOf.set(p, 'unit');
      roleOf.set(p === northCorner ? southCorner : northCorner, 'slack');
      clauses.push({ clause: unit.clause, point: p, literals: [unit.literal] });
      const dx = east ? x : x - CELL;
      const corners: [number, number, number, number] = [point(dx, y0), point(dx + CELL, y0), point(dx + CELL, y0 + WIDTH), point(dx, y0 + WIDTH)];
      north.add(corners[2]).add(corners[3]);
      if (east) last = cells.length;
      else first = cells.length;
      cells.push({ x: dx, y: y0, corners, wire: -1, avoid: p });
    });
    extremes.push([first, last]);
    next = cells[last]!.x + CELL;
  });

  // Rays: each wire point's neighbours along cell sides.
  const numWirePoints = xs.length;
  const rays = Array.from({ length: numWirePoints }, () => new Set<number>());
  for (const c of cells) {
    for (let s = 0; s < 4; s++) {
      const a = c.corners[s]!, b = c.corners[(s + 1) % 4]!;
      rays[a]!.add(b);
      rays[b]!.add(a);
    }
  }
  const roles: VertexRole[] = Array.from({ length: numWirePoints }, (_, i) => roleOf.get(i) ?? 'end');
  // The paper's Figure 9: a point just outside each cell's circle above and below
  // its middle (the cell stays flippable), and beside each free end.
  const r0 = Math.hypot(CELL / 2, WIDTH / 2);
  const out = r0 + GAP;
  // m[p]: the Figure 9 points next to wire point p, in order around it.
  const beside = Array.from({ length: numWirePoints }, () => [] as number[]);
  for (const c of cells) {
    const top = point(c.x + CELL / 2, c.y + WIDTH / 2 + out);
    const bottom = point(c.x + CELL / 2, c.y + WIDTH / 2 - out);
    roles.push('pendant', 'pendant');
    beside[c.corners[3]]!.push(top);
    beside[c.corners[2]]!.push(top);
    beside[c.corners[0]]!.push(bottom);
    beside[c.corners[1]]!.push(bottom);
  }
  // Only the two ends of the whole band: the chains follow each other along one
  // line, sharing a side where one ends and the next begins (both its corners
  // have room for the two diagonals, so the chains do not interact).
  {
    const firstCell = extremes[0]![0], lastCell = extremes[extremes.length - 1]![1];
    const first = cells[firstCell]!, last = cells[lastCell]!;
    const west = point(first.x + CELL / 2 - out, first.y + WIDTH / 2);
    const east = point(last.x + CELL / 2 + out, last.y + WIDTH / 2);
    roles.push('pendant', 'pendant');
    beside[first.corners[0]]!.push(west);
    beside[first.corners[3]]!.push(west);
    beside[last.corners[1]]!.push(east);
    beside[last.corners[2]]!.push(east);
  }
  const fixedDegree = rays.map((r, p) => r.size + beside[p]!.length);
  // Then, to reach its target, a point gets more neighbours on a circle through
  // its two Figure 9 points that holds it and the point across its cell (the
  // paper's "d - 6 more points on a circle"): a flip of any of its edges would
  // make a triangle with three corners on that circle, which holds two points,
  // so the edges stay fixed.
  for (const [p, target] of targets) {
    const extra = target - fixedDegree[p]!;
    if (extra === 0) continue;
    if (extra < 0 || beside[p]!.length !== 2) throw new Error(`internal: point ${p} has ${fixedDegree[p]} fixed neighbours, more than ${target}`);
    const across = acrossOf(p);
    const [a, b] = beside[p]!.map((i) => [xs[i]!, ys[i]!] as const) as [readonly [number, number], readonly [number, number]];
    // Centre: on the bisector of a and b, where the circle holds both p and the
    // point across deepest inside.
    const mx = (a[0] + b[0]) / 2, my = (a[1] + b[1]) / 2;
    const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
    const dx = -(b[1] - a[1]) / len, dy = (b[0] - a[0]) / len;
    const depth = (u: number) => {
      const ox = mx + u * dx, oy = my + u * dy;
      const rr = Math.hypot(a[0] - ox, a[1] - oy);
      return Math.min(rr - Math.hypot(xs[p]! - ox, ys[p]! - oy), rr - Math.hypot(xs[across]! - ox, ys[across]! - oy));
    };
    let u = 0;
    for (let k = -300; k <= 300; k++) if (depth(k / 200) > depth(u)) u = k / 200;
    if (depth(u) <= 0) throw new Error(`internal: no circle for point ${p}`);
    const cx = mx + u * dx, cy = my + u * dy;
    const r = Math.hypot(a[0] - cx, a[1] - cy);
    const ta = Math.atan2(a[1] - cy, a[0] - cx);
    let sweep = Math.atan2(b[1] - cy, b[0] - cx) - ta;
    sweep = ((sweep % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
    // The arc on p's side: the one beyond the chord ab from the point across.
    const middle = (sw: number) => [cx + r * Math.cos(ta + sw / 2), cy + r * Math.sin(ta + sw / 2)] as const;
    const side = (q: readonly [number, number]) => Math.sign((b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]));
    if (side(middle(sweep)) === side([xs[across]!, ys[across]!])) sweep -= 2 * Math.PI;
    const at = (u: number) => [cx + r * Math.cos(ta + u * sweep), cy + r * Math.sin(ta + u * sweep)] as const;
    for (let l = 1; l <= extra; l++) {
      const [x, y] = at(l / (extra + 1));
      point(x, y);
      roles.push('pendant');
    }
    fixedDegree[p] = target;
  }
  const points = new Float64Array(3 * xs.length);
  xs.forEach((x, i) => {
    points[3 * i] = x;
    points[3 * i + 1] = ys[i]!;
  });
  clauses.sort((a, b) => a.clause - b.clause);
  return { formula: f, points, numWirePoints, cells, wires, clauses, roles, fixedDegree, bound: DEGREE_BOUND, maxEdge: DEGREE_MAX_EDGE, chains };
}

