// The model of the Mixed vertices view (the paper's Section 3.1): a formula's
// gadget (build.ts), its terrain, what every assignment's triangulation scores
// (check.ts), the exact solve, and whether the reduction held on the instance.
import type { Hodt } from 'hodt';
import type { SolveJob } from '../../solver/solverClient.ts';
import { satisfyingAssignment } from '../formula.ts';
import { judgeReduction, parseGadgetFormula, type BuiltFormulaGadget, type Verdict } from '../gadgetModel.ts';
import { buildMixedGadget, type MixedGadget } from './build.ts';
import { certifyMixed, mapFanSectors, readMixedAssignment, type FanSectors, type MixedCertificate } from './check.ts';

export const DEFAULT_MIXED_FORMULA = 'x | y | z, !x | y, !y | w, !z';
export const MAX_VARIABLES = 6;

export type MixedBuilt = BuiltFormulaGadget<MixedGadget, FanSectors, MixedCertificate>;

/** The gadget of a formula, its terrain and the check of every assignment
 * (throws FormulaError or MixedLayoutError for a formula it cannot take). */
export function makeMixed(hodt: Hodt, text: string): MixedBuilt {
  const formula = parseGadgetFormula(text, 3, 'x | y | z, !x', MAX_VARIABLES);
  const gadget = buildMixedGadget(formula);
  const terrain = hodt.terrain(gadget.points);
  const map = mapFanSectors(gadget, terrain.quads);
  const certificate = certifyMixed(gadget, map, terrain.numQuads, (c) => terrain.evaluate(c)['min-mixed-vertices']);
  return { formula, gadget, terrain, map, satisfying: satisfyingAssignment(formula), certificate, solution: null, failure: null };
}

export const mixedJob = (b: MixedBuilt): SolveJob => ({ points: b.gadget.points, objective: 'min-mixed-vertices', method: 'exact', epsilon: 0.1, order: 1 });

/** Does the reduction hold on this instance, and if not, where does it fail? */
export function judgeMixed(b: MixedBuilt): Verdict {
  const floor = b.gadget.floor;
  const sat = b.satisfying !== null;
  const wrong = b.certificate.wrong.length;
  return judgeReduction(b.solution, (s) => ({
    per:
      wrong === 0
        ? `each of the ${b.certificate.values.length} assignments’ triangulations has ${floor} + (its false clauses) mixed vertices, and `
        : `${wrong} assignment(s) do not have ${floor} + (their false clauses) mixed vertices, and `,
    holds: (s.value === floor) === sat && s.value >= floor && wrong === 0,
    found: sat ? `= ${floor}, the floor, and the formula is satisfiable` : `> ${floor}, the floor, and the formula is unsatisfiable`,
    missed: ` against a floor of ${floor} while the formula is ${sat ? 'satisfiable' : 'unsatisfiable'}`,
  }));
}

export const mixedHooks = (b: MixedBuilt | null) => ({
  floor: b?.gadget.floor ?? null,
  assignment: b?.solution ? readMixedAssignment(b.gadget, b.map, b.solution.choice).assignment : null,
});
