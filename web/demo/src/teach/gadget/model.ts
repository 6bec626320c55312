// The model of the Hardness gadget view (the paper's Section 3.3): a MAX-2-SAT
// formula's gadget (build.ts), its terrain, the library's solve (most convex
// edges), the assignment read back from the pools, and the check that the
// pattern of every assignment scores a constant plus its satisfied clauses
// (check.ts), run a slice at a time.
import type { Hodt, Solution, Terrain } from 'hodt';
import type { SolveJob } from '../../solver/solverClient.ts';
import { maxSatisfiable, parseFormula, type Formula } from '../formula.ts';
import { buildGadget, type Gadget } from './build.ts';
import { certificateOf, mapCells, readBack, scoreAssignment, type CellQuads, type GadgetCertificate, type Readback } from './check.ts';

export const DEFAULT_FORMULA = 'x1 | x2, !x1 | x2, x1 | !x2, !x1 | !x2, x2 | x3, !x3 | x1';

export interface GadgetBuilt {
  formula: Formula;
  gadget: Gadget;
  terrain: Terrain;
  map: CellQuads;
  optimum: ReturnType<typeof maxSatisfiable>;
  solution: Solution | null;
  failure: string | null;
  readback: Readback | null;
  certificate: GadgetCertificate | null;
  /** Assignments certified so far (the check runs in slices). */
  checked: number;
}

/** The gadget of a formula and its terrain (throws FormulaError or LayoutError
 * for a formula it cannot take). */
export function makeGadget(hodt: Hodt, text: string): GadgetBuilt {
  const formula = parseFormula(text);
  const gadget = buildGadget(formula);
  const terrain = hodt.terrain(gadget.points);
  return { formula, gadget, terrain, map: mapCells(gadget, terrain.quads), optimum: maxSatisfiable(formula), solution: null, failure: null, readback: null, certificate: null, checked: 0 };
}

export const gadgetJob = (b: GadgetBuilt): SolveJob => ({ points: b.gadget.points, objective: 'max-convex-edges', method: 'auto', epsilon: 0.1, order: 1 });

/** Reads the solved gadget back (the pools' phases, the clause edges). */
export function readSolved(b: GadgetBuilt): void {
  if (b.solution) b.readback = readBack(b.gadget, b.map, b.solution.choice);
}

/** Scores the patterns of the next `count` assignments (the other quads as in the
 * solution) into values, and once all are scored sets the certificate; returns
 * whether any are left. The same check as certify() in check.ts, in slices. */
export function certifySlice(b: GadgetBuilt, values: number[], count: number): boolean {
  const total = 1 << b.formula.names.length;
  const evaluate = (choice: Uint8Array) => b.terrain.evaluate(choice)['max-convex-edges'];
  const end = Math.min(total, b.checked + count);
  for (let mask = b.checked; mask < end; mask++) values.push(scoreAssignment(evaluate, b.gadget, b.map, b.solution!.choice, mask));
  b.checked = end;
  if (end < total) return true;
  b.certificate = certificateOf(b.formula, values);
  return false;
}

/** Is the solver's proven optimum the constant plus the formula's optimum? */
export const isExact = (b: GadgetBuilt, cert: GadgetCertificate) => cert.constant !== null && b.solution!.optimal && b.solution!.value === cert.constant + b.optimum.best;

export function gadgetViewHooks(error: string | null, formula: string, b: GadgetBuilt | null): Record<string, unknown> {
  return {
    error,
    formula,
    variables: b?.formula.names ?? [],
    clauses: b ? b.formula.clauses.map((c) => c.map((l) => ({ variable: l.variable, negated: l.negated }))) : [],
    optimum: b?.optimum.best ?? null,
    points: b ? b.gadget.points.length / 3 : 0,
    solved: b?.solution != null,
    failure: b?.failure ?? null,
    value: b?.solution?.value ?? null,
    optimal: b?.solution?.optimal ?? null,
    method: b?.solution?.method ?? null,
    assignment: b?.readback?.assignment ?? null,
    edgeConvex: b?.readback?.edgeConvex ?? null,
    checked: b?.checked ?? 0,
    certificate: b?.certificate ? { constant: b.certificate.constant, tried: b.certificate.tried } : null,
  };
}
