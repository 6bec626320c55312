// The model of the Max degree view (the paper's Section 3.2): a formula's
// gadget (build.ts), its terrain in the domain the construction needs, what
// every assignment's triangulation scores (check.ts), the exact solve, and
// whether the reduction held on the instance.
import { judgeReduction, type BuiltFormulaGadget, type FormulaGadgetKind, type Verdict } from '../formulaGadget.ts';
import { buildDegreeGadget, DegreeLayoutError, type DegreeGadget } from './build.ts';
import { certifyDegree, mapDegreeCells, readDegreeAssignment, type DegreeCells, type DegreeCertificate } from './check.ts';

export const DEFAULT_DEGREE_FORMULA = 'x | y, !y | z, !x';

export type DegreeBuilt = BuiltFormulaGadget<DegreeGadget, DegreeCells, DegreeCertificate>;

/** Does the reduction hold on this instance: is the maximum degree at most d
 * exactly when the formula is satisfiable? */
function judgeDegree(b: DegreeBuilt): Verdict {
  const d = b.gadget.bound;
  return judgeReduction(b, {
    has: `maximum degree at most ${d} exactly when the assignment satisfies the formula`,
    break: `break “maximum degree at most ${d} exactly when satisfied”`,
    holds: (value, sat) => (value <= d) === sat,
    found: (sat) => `${sat ? '≤' : '>'} d = ${d}`,
  });
}

/** Clauses of one or two literals over at most 6 variables, laid out as rows of
 * cells, solved for the lowest maximum degree in the gadget's domain. */
export const degreeReduction: FormulaGadgetKind<DegreeGadget, DegreeCells, DegreeCertificate> = {
  maxLiterals: 2,
  maxVariables: 6,
  example: 'x | y, !x',
  objective: 'minmax-degree',
  layoutError: DegreeLayoutError,
  build: buildDegreeGadget,
  map: mapDegreeCells,
  certify: certifyDegree,
  read: readDegreeAssignment,
  judge: judgeDegree,
  hooks: (b) => ({ maxEdge: b?.gadget.maxEdge ?? null, bound: b?.gadget.bound ?? null }),
};
