// What a 3.1 or 3.2 reduction (Mixed vertices, Max degree) is to its view,
// without the DOM: its kind (the formulas it takes, how its gadget is built,
// mapped onto the terrain's quads, checked for every assignment, read and
// judged), the build of a formula, its exact solve, the verdict on a solved
// instance, and the view's hooks.
import type { Hodt, ObjectiveId } from 'hodt';
import type { SolveJob } from '../solver/solverClient.ts';
import { FormulaError, parseCnf, satisfyingAssignment, type Cnf, type Literal } from './formula.ts';
import type { BuiltGadget, GadgetRunner } from './gadgetModel.ts';

/** The points of a 3.1 or 3.2 gadget, its clause vertices, and the domain its
 * reduction is stated in (Terrain.maxEdge), if any. */
export interface FormulaGadget {
  points: Float64Array;
  clauses: readonly ClauseVertex[];
  maxEdge?: number;
}

/** A clause's vertex in a 3.1 or 3.2 gadget: the clause, its point, its literals. */
export interface ClauseVertex {
  clause: number;
  point: number;
  literals: Literal[];
}

/** The check of every assignment of a 3.1 or 3.2 gadget: what each scored, and
 * those that break the reduction. */
export interface AssignmentCheck {
  values: readonly number[];
  wrong: readonly unknown[];
}

/** What a 3.1 or 3.2 gadget's view reads from a triangulation: the value of each
 * variable, and how many of its quads disagree with it. */
export interface ReadValues {
  assignment: boolean[];
  disagreeing: number[];
}

/**
 * A 3.1 or 3.2 reduction as its view runs it, without the DOM: the formulas it
 * takes (`example` is shown with a formula it cannot parse), its construction
 * (throwing `layoutError` for a formula it cannot lay out), where its pieces are
 * among the terrain's quads (M), the check of every assignment by the objective
 * the view solves for (C), the values read from a triangulation, the verdict on
 * a solved instance, and its own hooks for the tests.
 */
export interface FormulaGadgetKind<G extends FormulaGadget, M, C extends AssignmentCheck> {
  maxLiterals: number;
  maxVariables: number;
  example: string;
  objective: ObjectiveId;
  layoutError: new (...args: never[]) => Error;
  build(formula: Cnf): G;
  map(gadget: G, quads: Uint32Array): M;
  certify(gadget: G, map: M, numQuads: number, value: (choice: Uint8Array) => number): C;
  read(gadget: G, map: M, choice: Uint8Array): ReadValues;
  judge(b: BuiltFormulaGadget<G, M, C>): Verdict;
  hooks(b: BuiltFormulaGadget<G, M, C> | null): Record<string, unknown>;
}

/** What a 3.1 or 3.2 gadget's view built: its formula, the gadget (G), where its
 * pieces are among the terrain's quads (M), and what every assignment scores (C). */
export interface BuiltFormulaGadget<G extends FormulaGadget = FormulaGadget, M = unknown, C extends AssignmentCheck = AssignmentCheck> extends BuiltGadget {
  formula: Cnf;
  gadget: G;
  map: M;
  satisfying: boolean[] | null;
  certificate: C;
}

/** Whether the reduction held on a built instance, in words. */
export interface Verdict {
  holds: boolean | null;
  text: string;
}

/** A formula for a gadget that takes clauses of 1 to maxLiterals literals over at
 * most maxVariables variables. */
function parseGadgetFormula(text: string, maxLiterals: number, example: string, maxVariables: number): Cnf {
  const formula = parseCnf(text, 1, maxLiterals, example);
  if (formula.names.length > maxVariables) throw new FormulaError(`${formula.names.length} variables: this gadget takes at most ${maxVariables}`);
  return formula;
}

/** The gadget of a formula, its terrain and the check of every assignment
 * (throws FormulaError, or the kind's layoutError, for a formula it cannot take). */
export function makeFormulaGadget<G extends FormulaGadget, M, C extends AssignmentCheck>(hodt: Hodt, text: string, kind: FormulaGadgetKind<G, M, C>): BuiltFormulaGadget<G, M, C> {
  const formula = parseGadgetFormula(text, kind.maxLiterals, kind.example, kind.maxVariables);
  const gadget = kind.build(formula);
  // maxEdge null is the library's default: every triangle is measured.
  const terrain = hodt.terrain(gadget.points, { maxEdge: gadget.maxEdge ?? null });
  const map = kind.map(gadget, terrain.quads);
  const certificate = kind.certify(gadget, map, terrain.numQuads, (c) => terrain.evaluate(c)[kind.objective]);
  return { formula, gadget, terrain, map, satisfying: satisfyingAssignment(formula), certificate, solution: null, failure: null };
}

/** The exact solve of a built 3.1 or 3.2 gadget, in the gadget's domain. */
export const formulaGadgetJob = (b: BuiltFormulaGadget<FormulaGadget>, objective: ObjectiveId): SolveJob => ({
  points: b.gadget.points,
  objective,
  method: 'exact',
  epsilon: 0.1,
  order: 1,
  maxEdge: b.gadget.maxEdge ?? null,
});

/**
 * The verdict on a solved 3.1 or 3.2 instance: unverified unless the optimum is
 * proven; else it holds when every assignment's triangulation scored as the
 * proof says (each `has` it; the wrong ones `break` it, in words) and the
 * optimum is what the proof predicts for the formula (`holds`): `found` says how
 * it compares when it holds, `against` what it was measured against when not.
 */
export function judgeReduction(
  b: BuiltFormulaGadget,
  claim: { has: string; break: string; holds(value: number, satisfiable: boolean): boolean; found(satisfiable: boolean): string; against?: string },
): Verdict {
  const s = b.solution;
  if (!s) return { holds: null, text: '' };
  if (!s.optimal) return { holds: false, text: `The solver’s ${s.value} is not proven optimal, so this instance is not verified.` };
  const sat = b.satisfying !== null;
  const wrong = b.certificate.wrong.length;
  const per = wrong === 0 ? `each of the ${b.certificate.values.length} assignments’ triangulations has ${claim.has}, and ` : `${wrong} assignment(s) ${claim.break}, and `;
  const formula = `the formula is ${sat ? 'satisfiable' : 'unsatisfiable'}`;
  return claim.holds(s.value, sat) && wrong === 0
    ? { holds: true, text: `Check: ${per}the proven optimum is ${s.value} ${claim.found(sat)}, and ${formula}: on this instance the reduction holds.` }
    : { holds: false, text: `Check failed: ${per}the proven optimum is ${s.value}${claim.against ?? ''} while ${formula}: on this instance the reduction does not hold.` };
}

/** The hooks (tests/e2e) of a 3.1 or 3.2 gadget's view: what every one shares, and the kind's own. */
export function formulaGadgetHooks<G extends FormulaGadget, M, C extends AssignmentCheck>(
  runner: GadgetRunner<BuiltFormulaGadget<G, M, C>>,
  formula: string,
  kind: FormulaGadgetKind<G, M, C>,
): Record<string, unknown> {
  const b = runner.built;
  return {
    error: runner.error,
    formula,
    points: b ? Array.from(b.gadget.points) : [],
    satisfiable: b ? b.satisfying !== null : null,
    solved: b?.solution != null,
    failure: b?.failure ?? null,
    value: b?.solution?.value ?? null,
    optimal: b?.solution?.optimal ?? null,
    wrongAssignments: b ? b.certificate.wrong.length : null,
    holds: b ? kind.judge(b).holds : null,
    ...kind.hooks(b),
  };
}
