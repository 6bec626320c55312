// The model of the Max degree view (the paper's Section 3.2): a formula's
// gadget (build.ts), its terrain in the domain the construction needs, what
// every assignment's triangulation scores (check.ts), the exact solve, and
// whether the reduction held on the instance.
import type { Hodt } from 'hodt';
import { satisfyingAssignment } from '../formula.ts';
import { judgeReduction, parseGadgetFormula, type BuiltFormulaGadget, type Verdict } from '../gadgetModel.ts';
import type { SolveJob } from '../../solver/solverClient.ts';
import { buildDegreeGadget, type DegreeGadget } from './build.ts';
import { certifyDegree, mapDegreeCells, type DegreeCells, type DegreeCertificate } from './check.ts';

export const DEFAULT_DEGREE_FORMULA = 'x | y, !y | z, !x';
export const MAX_VARIABLES = 6;

export type DegreeBuilt = BuiltFormulaGadget<DegreeGadget, DegreeCells, DegreeCertificate>;

/** The gadget of a formula, its terrain and the check of every assignment
 * (throws FormulaError or DegreeLayoutError for a formula it cannot take). */
export function makeDegree(hodt: Hodt, text: string): DegreeBuilt {
  const formula = parseGadgetFormula(text, 2, 'x | y, !x', MAX_VARIABLES);
  const gadget = buildDegreeGadget(formula);
  const terrain = hodt.terrain(gadget.points, { maxEdge: gadget.maxEdge });
  const map = mapDegreeCells(gadget, terrain.quads);
  const certificate = certifyDegree(gadget, map, terrain.numQuads, (c) => terrain.evaluate(c)['minmax-degree']);
  return { formula, gadget, terrain, map, satisfying: satisfyingAssignment(formula), certificate, solution: null, failure: null };
}

export const degreeJob = (b: DegreeBuilt): SolveJob => ({ points: b.gadget.points, objective: 'minmax-degree', method: 'exact', epsilon: 0.1, order: 1, maxEdge: b.gadget.maxEdge });

/** Does the reduction hold on this instance, and if not, where does it fail? */
export function judgeDegree(b: DegreeBuilt): Verdict {
  const d = b.gadget.bound;
  const sat = b.satisfying !== null;
  const wrong = b.certificate.wrong.length;
  return judgeReduction(b.solution, (s) => ({
    per:
      wrong === 0
        ? `each of the ${b.certificate.values.length} assignments’ triangulations has maximum degree at most ${d} exactly when the assignment satisfies the formula, and `
        : `${wrong} assignment(s) break “maximum degree at most ${d} exactly when satisfied”, and `,
    holds: (s.value <= d) === sat && wrong === 0,
    found: sat ? `≤ d = ${d}, and the formula is satisfiable` : `> d = ${d}, and the formula is unsatisfiable`,
    missed: ` while the formula is ${sat ? 'satisfiable' : 'unsatisfiable'}`,
  }));
}

export const degreeHooks = (b: DegreeBuilt | null) => ({ maxEdge: b?.gadget.maxEdge ?? null, bound: b?.gadget.bound ?? null });
