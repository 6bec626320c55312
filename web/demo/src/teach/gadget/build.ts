// The NP-hardness construction of Section 3.3 (maximising convex edges), built
// from a small MAX-2-SAT formula:
//
// - a grid of unit quads with heights f(x, y) = xy - (x^2 + y^2) / 10: in every
//   quad the SW-NE diagonal is convex and the other reflex, and an edge between
//   two quads is convex unless both quads use their convex diagonal;
// - a rectangular pool of quads per variable along a horizontal spine: its best
//   states are the two chessboard patterns, its phase is the variable's value;
// - per clause, a tentacle (a path of quads) from each of its two pools, above or
//   below the spine, meeting the other at a single shared edge, which is convex
//   (a credit) when at least one of the two end quads is reflex; which end state
//   means "literal true" is set by where the tentacle leaves its pool, and a
//   tentacle that would end with the wrong parity skips a column (one 2 x 1 quad,
//   the paper's Figure 13(a));
// - a coating: every other lattice point is high, and lattice squares touching
//   the gadget get a high point in the middle, so every edge on the gadget's
//   border is reflex whatever the quads do (Figure 13(b)).
//
// The paper proves the reduction for planar formulas; here the formula must have
// a drawing with the variables on a line and the clauses as nested arcs above and
// below it (found by search). Whether the solver's optimum really decodes to an
// optimal assignment is checked on every instance by the view (check.ts).
import type { Formula } from '../formula.ts';

export interface GadgetCell {
  /** Lower-left lattice corner and size (1 x 1, or 2 x 1 for a skip). */
  x: number;
  y: number;
  w: number;
  /** Point indices of the corners: south-west, south-east, north-east, north-west. */
  corners: [number, number, number, number];
  /** The variable whose pool or tentacle this is. */
  variable: number;
  /** -1 in a pool, else the clause of the tentacle. */
  clause: number;
  /** In a tentacle: position from the pool (0 next to the pool), else -1. */
  step: number;
}

export interface GadgetTentacle {
  variable: number;
  negated: boolean;
  /** The pool cell it leaves from (q0) and its cells, from the pool outwards. */
  root: number;
  cells: number[];
}

export interface GadgetClause {
  page: 'top' | 'bottom';
  level: number;
  skip: boolean;
  tentacles: [GadgetTentacle, GadgetTentacle];
}

export interface Gadget {
  formula: Formula;
  /** x, y, z per point: the gadget's lattice points first, then the coating. */
  points: Float64Array;
  /** Points with index below this are gadget (low) points. */
  numLow: number;
  cells: GadgetCell[];
  pools: { variable: number; x0: number; y0: number; w: number; h: number; cells: number[] }[];
  clauses: GadgetClause[];
  /** Variables in spine order. */
  order: number[];
  bounds: { x0: number; y0: number; x1: number; y1: number };
  /** Height of the coating points. */
  high: number;
}

export class LayoutError extends Error {
  override name = 'LayoutError';
}

export const f = (x: number, y: number) => x * y - (x * x + y * y) / 10;

const LEG_SPACING = 3;
const LEVEL_SPACING = 3;
const POOL_GAP = 4;
const MARGIN = 2;
/** Pool height for a variable with k tentacles: 2k (even, at least 4), capped so that
 * the exact solver's tree decomposition stays within its memory cap. */
let poolCap = 8;
export function setPoolCap(cap: number): void {
  poolCap = cap;
}
const POOL_HEIGHT = (k: number) => Math.min(poolCap, Math.max(4, 2 * k));

interface Arc {
  clause: number;
  lo: number; // spine positions, lo < hi
  hi: number;
}

/** Variable order along the spine and a page per clause such that arcs on one
 * page never cross, or null. Tries the order of first appearance, then others. */
export function findLayout(formula: Formula): { order: number[]; page: ('top' | 'bottom')[] } | null {
  const n = formula.names.length;
  const tryOrder = (order: number[]) => {
    const pos = new Int32Array(n);
    order.forEach((v, i) => (pos[v] = i));
    const arcs = formula.clauses.map((c, k) => {
      const a = pos[c[0].variable]!, b = pos[c[1].variable]!;
      return { clause: k, lo: Math.min(a, b), hi: Math.max(a, b) };
    });
    const crosses = (s: Arc, t: Arc) => (s.lo < t.lo && t.lo < s.hi && s.hi < t.hi) || (t.lo < s.lo && s.lo < t.hi && t.hi < s.hi);
    const page = new Int8Array(arcs.length).fill(-1);
    let top = 0;
    for (let s = 0; s < arcs.length; s++) {
      if (page[s]! >= 0) continue;
      const component: number[] = [s];
      page[s] = 0;
      for (let i = 0; i < component.length; i++) {
        const a = component[i]!;
        for (let b = 0; b < arcs.length; b++) {
          if (b === a || !crosses(arcs[a]!, arcs[b]!)) continue;
          if (page[b]! < 0) {
            page[b] = 1 - page[a]!;
            component.push(b);
          } else if (page[b] === page[a]) return null;
        }
      }
      // Balance the pages: put the larger half of this component where fewer are.
      const zeros = component.filter((a) => page[a] === 0).length;
      const flip = top > formula.clauses.length / 2 === zeros >= component.length - zeros;
      if (flip) for (const a of component) page[a] = 1 - page[a]!;
      top += component.filter((a) => page[a] === 0).length;
    }
    return Array.from(page, (p) => (p === 0 ? 'top' : 'bottom') as 'top' | 'bottom');
  };
  const identity = Array.from({ length: n }, (_, i) => i);
  let page = tryOrder(identity);
  if (page) return { order: identity, page };
  // Deterministic pseudo-random orders (Heap's algorithm would be n! for n = 10).
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) & 0x7fffffff) / 0x80000000);
  for (let attempt = 0; attempt < 4000; attempt++) {
    const order = identity.slice();
    for (let i = n - 1; i > 0; i--) {
      const j = Math.floor(random() * (i + 1));
      [order[i], order[j]] = [order[j]!, order[i]!];
    }
    page = tryOrder(order);
    if (page) return { order, page };
  }
  return null;
}

export function buildGadget(formula: Formula): Gadget {
  const layout = findLayout(formula);
  if (!layout) {
    throw new LayoutError(
      'this formula cannot be drawn with its variables on a line and its clauses as non-crossing arcs above and below it; ' +
        'the construction needs a planar formula (the paper reduces from planar MAX-2-SAT)',
    );
  }
  const n = formula.names.length;
  const { order, page } = layout;
  const pos = new Int32Array(n);
  order.forEach((v, i) => (pos[v] = i));
  const arcs = formula.clauses.map((c, k) => {
    const a = pos[c[0].variable]!, b = pos[c[1].variable]!;
    return { clause: k, lo: Math.min(a, b), hi: Math.max(a, b), page: page[k]! };
  });
  // Nesting levels per page: 1 + the highest level of the arcs inside.
  const level = new Int32Array(arcs.length).fill(-1);
  const inside = (s: (typeof arcs)[number], t: (typeof arcs)[number]) =>
    s.page === t.page && s.lo <= t.lo && t.hi <= s.hi && (s.lo !== t.lo || s.hi !== t.hi || t.clause < s.clause);
  const levelOf = (k: number): number => {
    if (level[k]! >= 0) return level[k]!;
    let l = 0;
    for (let j = 0; j < arcs.length; j++) if (j !== k && inside(arcs[k]!, arcs[j]!)) l = Math.max(l, levelOf(j) + 1);
    return (level[k] = l);
  };
  arcs.forEach((_, k) => levelOf(k));

  // Pool height: a break line across a pool costs half its length, so a pool at
  // least twice as high as a variable's number of tentacles never splits.
  const occurrences = new Int32Array(n);
  for (const c of formula.clauses) for (const l of c) occurrences[l.variable]!++;
  const ph = POOL_HEIGHT(Math.max(0, ...occurrences));

  // Attachment columns: per pool and page, arcs going left (inner first) then
  // arcs going right (outer first), LEG_SPACING apart, each on the column parity
  // that makes its end quad reflex exactly when its literal is true.
  const attach = new Map<string, number>(); // `${clause}:${variable}` -> column
  const pools: Gadget['pools'] = [];
  let x0 = 0;
  for (let i = 0; i < n; i++) {
    const v = order[i]!;
    let right = x0 + 3;
    for (const side of ['top', 'bottom'] as const) {
      const here = arcs.filter((a) => a.page === side && (a.lo === i || a.hi === i));
      const leftGoing = here.filter((a) => a.hi === i).sort((s, t) => level[s.clause]! - level[t.clause]!);
      const rightGoing = here.filter((a) => a.lo === i).sort((s, t) => level[t.clause]! - level[s.clause]!);
      let col = x0 + 1;
      for (const a of [...leftGoing, ...rightGoing]) {
        const lit = formula.clauses[a.clause]!.find((l) => l.variable === v)!;
        const rootRow = side === 'top' ? ph - 1 : 0;
        // Positive literal: the pool quad under the tentacle has even x + y.
        while ((((col + rootRow) % 2) + 2) % 2 !== (lit.negated ? 1 : 0)) col++;
        attach.set(`${a.clause}:${v}`, col);
        right = Math.max(right, col + 2);
        col += LEG_SPACING;
      }
    }
    const w = Math.max(4, right - x0) + (Math.max(4, right - x0) % 2);
    pools.push({ variable: v, x0, y0: 0, w, h: ph, cells: [] });
    x0 += w + POOL_GAP;
  }

  // Cells. Points are numbered later; cells keep lattice coordinates for now.
  type RawCell = { x: number; y: number; w: number; variable: number; clause: number; step: number };
  const raw: RawCell[] = [];
  const removed = new Set<string>();
  const key = (x: number, y: number) => `${x},${y}`;
  pools.forEach((pool, i) => {
    for (let y = 0; y < pool.h; y++) {
      for (let x = pool.x0; x < pool.x0 + pool.w; x++) {
        pool.cells.push(raw.length);
        raw.push({ x, y, w: 1, variable: order[i]!, clause: -1, step: -1 });
      }
    }
  });
  const poolCell = (i: number, x: number, y: number) => pools[i]!.cells[(y - pools[i]!.y0) * pools[i]!.w + (x - pools[i]!.x0)]!;

  const clauses: GadgetClause[] = [];
  let yMin = 0, yMax = ph;
  arcs.forEach((arc, k) => {
    const clause = formula.clauses[k]!;
    const vLo = order[arc.lo]!, vHi = order[arc.hi]!;
    const a = attach.get(`${k}:${vLo}`)!, b = attach.get(`${k}:${vHi}`)!;
    const lvl = level[k]!;
    const top = arc.page === 'top';
    const row = top ? ph + 2 + LEVEL_SPACING * lvl : -3 - LEVEL_SPACING * lvl;
    yMin = Math.min(yMin, row);
    yMax = Math.max(yMax, row + 1);
    const legRows: number[] = [];
    if (top) for (let y = ph; y < row; y++) legRows.push(y);
    else for (let y = -1; y > row; y--) legRows.push(y);
    let path: { x: number; y: number; w: number }[] = [
      ...legRows.map((y) => ({ x: a, y, w: 1 })),
      ...Array.from({ length: b - a + 1 }, (_, i) => ({ x: a + i, y: row, w: 1 })),
      ...legRows.slice().reverse().map((y) => ({ x: b, y, w: 1 })),
    ];
    let skip = false;
    if (path.length % 2 === 1) {
      // Skip a column in the middle of the arc: a 2 x 1 quad.
      const s = Math.floor((a + b) / 2) - 1;
      if (s < a + 2 || s + 2 > b - 1) throw new LayoutError('internal: an arc is too short for a skip');
      path = path.filter((c) => !(c.y === row && (c.x === s || c.x === s + 1)));
      const at = path.findIndex((c) => c.y === row && c.x === s + 2);
      path.splice(at, 0, { x: s, y: row, w: 2 });
      removed.add(key(s + 1, row));
      removed.add(key(s + 1, row + 1));
      skip = true;
    }
    // Split into two even halves meeting in the horizontal part.
    const legs = legRows.length;
    const half = path.length / 2;
    let split = -1;
    for (let d = 0; d <= half && split < 0; d++) {
      for (const c of [half - d, half + d]) {
        if (c % 2 === 0 && c >= 2 && path.length - c >= 2 && c - 1 >= legs && c <= path.length - 1 - legs) {
          split = c;
          break;
        }
      }
    }
    if (split < 0) throw new LayoutError('internal: no meeting point for a clause');
    const make = (cells: typeof path, variable: number, rootX: number): GadgetTentacle => {
      const lit = clause.find((l) => l.variable === variable)!;
      const root = poolCell(pos[variable]!, rootX, top ? ph - 1 : 0);
      const ids = cells.map((c, step) => {
        raw.push({ ...c, variable, clause: k, step });
        return raw.length - 1;
      });
      return { variable, negated: lit.negated, root, cells: ids };
    };
    const tLo = make(path.slice(0, split), vLo, a);
    const tHi = make(path.slice(split).reverse(), vHi, b);
    const first = clause[0].variable === vLo ? tLo : tHi;
    const second = first === tLo ? tHi : tLo;
    clauses.push({ page: arc.page, level: lvl, skip, tentacles: [first, second] });
  });

  // Lattice points: gadget corners low at f(x, y), the rest high, and a high
  // point in the middle of every other lattice square that touches the gadget.
  const bounds = { x0: -MARGIN, y0: yMin - MARGIN, x1: x0 - POOL_GAP + MARGIN, y1: yMax + MARGIN };
  const lowKeys = new Set<string>();
  const covered = new Set<string>();
  for (const c of raw) {
    for (const [dx, dy] of [[0, 0], [c.w, 0], [c.w, 1], [0, 1]] as const) lowKeys.add(key(c.x + dx, c.y + dy));
    for (let i = 0; i < c.w; i++) covered.add(key(c.x + i, c.y));
  }
  const index = new Map<string, number>();
  const xyz: number[] = [];
  let lowMin = Infinity, lowMax = -Infinity;
  for (let y = bounds.y0; y <= bounds.y1; y++) {
    for (let x = bounds.x0; x <= bounds.x1; x++) {
      if (!lowKeys.has(key(x, y))) continue;
      index.set(key(x, y), xyz.length / 3);
      const z = f(x, y);
      lowMin = Math.min(lowMin, z);
      lowMax = Math.max(lowMax, z);
      xyz.push(x, y, z);
    }
  }
  const numLow = xyz.length / 3;
  const high = Math.ceil(lowMax + 3 * (lowMax - lowMin) + 10);
  for (let y = bounds.y0; y <= bounds.y1; y++) {
    for (let x = bounds.x0; x <= bounds.x1; x++) {
      const k = key(x, y);
      if (lowKeys.has(k) || removed.has(k)) continue;
      index.set(k, xyz.length / 3);
      xyz.push(x, y, high);
    }
  }
  for (let y = bounds.y0; y < bounds.y1; y++) {
    for (let x = bounds.x0; x < bounds.x1; x++) {
      if (covered.has(key(x, y))) continue;
      const corners = [key(x, y), key(x + 1, y), key(x + 1, y + 1), key(x, y + 1)];
      if (corners.some((c) => removed.has(c)) || !corners.some((c) => lowKeys.has(c))) continue;
      xyz.push(x + 0.5, y + 0.5, high);
    }
  }
  const cells: GadgetCell[] = raw.map((c) => ({
    ...c,
    corners: [index.get(key(c.x, c.y))!, index.get(key(c.x + c.w, c.y))!, index.get(key(c.x + c.w, c.y + 1))!, index.get(key(c.x, c.y + 1))!],
  }));
  return { formula, points: Float64Array.from(xyz), numLow, cells, pools, clauses, order, bounds, high };
}
