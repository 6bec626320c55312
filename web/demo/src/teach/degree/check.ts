// Reading a triangulation of the Section 3.2 gadget back as an assignment, and the
// per-instance check that the construction behaves as the proof says.
import { literalTrue, type Cnf } from '../formula.ts';
import type { DegreeGadget, VertexRole } from './build.ts';

const FIXED_ROLES = new Set<VertexRole>(['wire', 'clause', 'unit']);

/** Which library quad each cell is, and whether its Delaunay diagonal rises
 * (south-west to north-east). */
export interface DegreeCells {
  quad: Int32Array;
  delaunayRises: Uint8Array;
  /** Flippable quads of the terrain that are not cells (in the filling, none
   * with a corner on a wire point whose degree the construction fixes). */
  otherQuads: number;
  /** Of those, the ones with a corner the construction gives a fixed degree to. */
  otherQuadsAtFixedPoints: number;
}

export function mapDegreeCells(g: DegreeGadget, quads: Uint32Array): DegreeCells {
  const byCorners = new Map<string, number>();
  const key = (a: ArrayLike<number>) => Array.from(a).sort((x, y) => x - y).join(',');
  for (let q = 0; q < quads.length / 4; q++) byCorners.set(key(quads.subarray(4 * q, 4 * q + 4)), q);
  const quad = new Int32Array(g.cells.length);
  const delaunayRises = new Uint8Array(g.cells.length);
  g.cells.forEach((c, i) => {
    const q = byCorners.get(key(c.corners));
    if (q === undefined) throw new Error(`cell at (${c.x}, ${c.y}) is not a flippable quad of the terrain`);
    quad[i] = q;
    const a = quads[4 * q]!, b = quads[4 * q + 1]!;
    const [sw, , ne] = c.corners;
    delaunayRises[i] = (a === sw && b === ne) || (a === ne && b === sw) ? 1 : 0;
  });
  const cellQuads = new Set(quad);
  let atFixed = 0;
  for (let q = 0; q < quads.length / 4; q++) {
    if (cellQuads.has(q)) continue;
    const corners = Array.from(quads.subarray(4 * q, 4 * q + 4));
    if (corners.some((p) => FIXED_ROLES.has(g.roles[p]!))) atFixed++;
  }
  return { quad, delaunayRises, otherQuads: quads.length / 4 - g.cells.length, otherQuadsAtFixedPoints: atFixed };
}

/** The triangulation of an assignment: every cell of a wire rising when its
 * variable's value is the wire's rising value, every dummy cell's diagonal away
 * from its clause corner, other quads Delaunay. */
export function degreeChoice(g: DegreeGadget, map: DegreeCells, assignment: readonly boolean[], numQuads: number): Uint8Array {
  const choice = new Uint8Array(numQuads);
  for (const w of g.wires) {
    const rises = assignment[w.variable] === w.risingIsTrue;
    for (const c of w.cells) choice[map.quad[c]!] = rises === (map.delaunayRises[c] === 1) ? 0 : 1;
  }
  g.cells.forEach((cell, c) => {
    if (cell.wire >= 0) return;
    const rises = cell.avoid !== cell.corners[0] && cell.avoid !== cell.corners[2];
    choice[map.quad[c]!] = rises === (map.delaunayRises[c] === 1) ? 0 : 1;
  });
  return choice;
}

/** Per wire: the value its cells vote for, and how many cells disagree. */
export function readDegreeAssignment(g: DegreeGadget, map: DegreeCells, choice: Uint8Array): { assignment: boolean[]; disagreeing: number[] } {
  const assignment = new Array<boolean>(g.formula.names.length).fill(false);
  const disagreeing = new Array<number>(g.formula.names.length).fill(0);
  for (const w of g.wires) {
    const rises = w.cells.map((c) => (choice[map.quad[c]!] === 0) === (map.delaunayRises[c] === 1));
    const up = rises.filter(Boolean).length;
    const value = up * 2 >= rises.length ? w.risingIsTrue : !w.risingIsTrue;
    assignment[w.variable] = value;
    disagreeing[w.variable] = Math.min(up, rises.length - up);
  }
  return { assignment, disagreeing };
}

export const satisfies = (f: Cnf, a: readonly boolean[]) => f.clauses.every((c) => c.some((l) => literalTrue(l, a)));

export interface DegreeCertificate {
  /** Per assignment (bit v of the index = variable v): max degree of its triangulation. */
  values: number[];
  /** Assignments whose triangulation breaks "max degree <= d iff satisfied". */
  wrong: number[];
}

/** Max degree of every assignment's triangulation, against its satisfaction. */
export function certifyDegree(g: DegreeGadget, map: DegreeCells, numQuads: number, maxDegree: (choice: Uint8Array) => number): DegreeCertificate {
  const n = g.formula.names.length;
  const values: number[] = [];
  const wrong: number[] = [];
  for (let mask = 0; mask < 1 << n; mask++) {
    const a = Array.from({ length: n }, (_, v) => ((mask >> v) & 1) === 1);
    const value = maxDegree(degreeChoice(g, map, a, numQuads));
    values.push(value);
    if (value <= g.bound !== satisfies(g.formula, a)) wrong.push(mask);
  }
  return { values, wrong };
}
