// The model of the Mixed vertices view (the paper's Section 3.1): a formula's
// gadget (build.ts), its terrain, what every assignment's triangulation scores
// (check.ts), the exact solve, and whether the reduction held on the instance.
import { judgeReduction, type BuiltFormulaGadget, type FormulaGadgetKind, type Verdict } from '../formulaGadget.ts';
import { buildMixedGadget, MixedLayoutError, type MixedGadget } from './build.ts';
import { certifyMixed, mapFanSectors, readMixedAssignment, type FanSectors, type MixedCertificate } from './check.ts';

export const DEFAULT_MIXED_FORMULA = 'x | y | z, !x | y, !y | w, !z';

export type MixedBuilt = BuiltFormulaGadget<MixedGadget, FanSectors, MixedCertificate>;

/** Does the reduction hold on this instance: are the fewest mixed vertices the
 * floor exactly when the formula is satisfiable (and never fewer)? */
function judgeMixed(b: MixedBuilt): Verdict {
  const floor = b.gadget.floor;
  return judgeReduction(b, {
    has: `${floor} + (its false clauses) mixed vertices`,
    break: `do not have ${floor} + (their false clauses) mixed vertices`,
    holds: (value, sat) => (value === floor) === sat && value >= floor,
    found: (sat) => `${sat ? '=' : '>'} ${floor}, the floor`,
    against: ` against a floor of ${floor}`,
  });
}

/** Clauses of one to three literals over at most 6 variables, a fan per
 * variable on a hexagonal grid, solved for the fewest mixed vertices. */
export const mixedReduction: FormulaGadgetKind<MixedGadget, FanSectors, MixedCertificate> = {
  maxLiterals: 3,
  maxVariables: 6,
  example: 'x | y | z, !x',
  objective: 'min-mixed-vertices',
  layoutError: MixedLayoutError,
  build: buildMixedGadget,
  map: mapFanSectors,
  certify: certifyMixed,
  read: readMixedAssignment,
  judge: judgeMixed,
  hooks: (b) => ({
    floor: b?.gadget.floor ?? null,
    assignment: b?.solution ? readMixedAssignment(b.gadget, b.map, b.solution.choice).assignment : null,
  }),
};
