// Reading a triangulation of the hardness gadget back as an assignment, and the
// per-instance check that the construction behaves as Section 3.3 says.
import { countSatisfied, type Formula } from '../formula.ts';
import type { Gadget } from './build.ts';

/** Which library quad each gadget cell is, and whether its Delaunay diagonal is
 * the convex (south-west to north-east) one. */
export interface CellQuads {
  quad: Int32Array;
  delaunayIsConvex: Uint8Array;
}

export function mapCells(g: Gadget, quads: Uint32Array): CellQuads {
  const byCorners = new Map<string, number>();
  const sorted = (a: number[]) => a.slice().sort((x, y) => x - y).join(',');
  for (let q = 0; q < quads.length / 4; q++) byCorners.set(sorted(Array.from(quads.subarray(4 * q, 4 * q + 4))), q);
  const quad = new Int32Array(g.cells.length);
  const delaunayIsConvex = new Uint8Array(g.cells.length);
  g.cells.forEach((c, i) => {
    const q = byCorners.get(sorted(c.corners));
    if (q === undefined) throw new Error(`gadget cell at (${c.x}, ${c.y}) is not a flippable quad of the terrain`);
    quad[i] = q;
    const [sw, , ne] = c.corners;
    const a = quads[4 * q]!, b = quads[4 * q + 1]!;
    delaunayIsConvex[i] = (a === sw && b === ne) || (a === ne && b === sw) ? 1 : 0;
  });
  return { quad, delaunayIsConvex };
}

/** Convex (true) or reflex state of every cell in the pattern of an assignment:
 * each pool a chessboard in its variable's phase (phase 1 = true: the quad at
 * (x, y) is convex iff x + y is odd), each tentacle alternating from its pool. */
export function canonicalStates(g: Gadget, assignment: readonly boolean[]): boolean[] {
  const convex = new Array<boolean>(g.cells.length).fill(false);
  const poolConvex = (cell: number) => {
    const c = g.cells[cell]!;
    const p = assignment[c.variable] ? 1 : 0;
    return (((c.x + c.y + p) % 2) + 2) % 2 === 0;
  };
  g.cells.forEach((c, i) => {
    if (c.clause < 0) convex[i] = poolConvex(i);
  });
  for (const clause of g.clauses) {
    for (const t of clause.tentacles) {
      const root = poolConvex(t.root);
      t.cells.forEach((cell, step) => (convex[cell] = step % 2 === 0 ? !root : root));
    }
  }
  return convex;
}

/** A choice with the given cell states; other quads as in `base`. */
export function choiceFor(map: CellQuads, states: readonly boolean[], base: Uint8Array): Uint8Array {
  const choice = base.slice();
  states.forEach((convex, i) => (choice[map.quad[i]!] = convex === (map.delaunayIsConvex[i] === 1) ? 0 : 1));
  return choice;
}

export function cellStates(map: CellQuads, choice: Uint8Array): boolean[] {
  return Array.from(map.quad, (q, i) => (choice[q] === 0) === (map.delaunayIsConvex[i] === 1));
}

export interface Readback {
  assignment: boolean[];
  /** Per variable: fraction of its pool in the majority phase (1 = a clean chessboard). */
  agreement: number[];
  /** Per clause: is its meeting edge convex (one of the two end quads reflex)? */
  edgeConvex: boolean[];
  /** Per clause: cells of its tentacles off the pattern of the read assignment. */
  defects: number[];
}

export function readBack(g: Gadget, map: CellQuads, choice: Uint8Array): Readback {
  const convex = cellStates(map, choice);
  const n = g.formula.names.length;
  const votes = Array.from({ length: n }, () => [0, 0]);
  g.cells.forEach((c, i) => {
    if (c.clause >= 0) return;
    const p = (((c.x + c.y + (convex[i] ? 0 : 1)) % 2) + 2) % 2;
    votes[c.variable]![p]!++;
  });
  const assignment = votes.map(([zero, one]) => one! > zero!);
  const agreement = votes.map(([zero, one]) => Math.max(zero!, one!) / Math.max(1, zero! + one!));
  const pattern = canonicalStates(g, assignment);
  const edgeConvex = g.clauses.map((cl) => cl.tentacles.some((t) => !convex[t.cells[t.cells.length - 1]!]));
  const defects = g.clauses.map((cl) => cl.tentacles.reduce((s, t) => s + t.cells.filter((c) => convex[c] !== pattern[c]).length, 0));
  return { assignment, agreement, edgeConvex, defects };
}

export interface GadgetCertificate {
  /** value(pattern of a) - satisfied(a), the same for every assignment a? */
  constant: number | null;
  /** Assignments tried (all 2^n). */
  tried: number;
  /** Convex edges of the pattern of each assignment. */
  values: number[];
}

/** The assignment of a bit mask: variable v is true when bit v is set. */
export const assignmentOf = (mask: number, n: number) => Array.from({ length: n }, (_, v) => ((mask >> v) & 1) === 1);

/** The convex edges of the pattern of assignment `mask` (other quads as in base). */
export const scoreAssignment = (evaluate: (choice: Uint8Array) => number, g: Gadget, map: CellQuads, base: Uint8Array, mask: number) =>
  evaluate(choiceFor(map, canonicalStates(g, assignmentOf(mask, g.formula.names.length)), base));

/** The check on the patterns' values (one per assignment, by mask): each must be
 * a constant plus its satisfied clauses. */
export function certificateOf(formula: Formula, values: number[]): GadgetCertificate {
  const n = formula.names.length;
  const constants = values.map((v, mask) => v - countSatisfied(formula, assignmentOf(mask, n)));
  return { constant: constants.every((c) => c === constants[0]) ? constants[0]! : null, tried: values.length, values };
}

/** Evaluates the pattern of every assignment (with the other quads as in base)
 * and checks that its convex edges are a constant plus its satisfied clauses. */
export function certify(formula: Formula, evaluate: (choice: Uint8Array) => number, g: Gadget, map: CellQuads, base: Uint8Array): GadgetCertificate {
  const values = Array.from({ length: 1 << formula.names.length }, (_, mask) => scoreAssignment(evaluate, g, map, base, mask));
  return certificateOf(formula, values);
}
