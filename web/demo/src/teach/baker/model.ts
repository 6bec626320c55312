// The model of the Baker layers view (the paper's Section 4): the library's run
// of Baker's scheme (terrain.explain with the approximation) on the page's
// terrain: each quad's layer, lambda, and per shift what it cut, the optimum of
// what it keeps, its triangulation's value and its bound. Positions: 0 the
// layers, 1 to lambda the shifts, lambda + 1 the result.
import type { BakerExplanation, ObjectiveId, Solution } from 'hodt';
import type { SolveOutcome } from '../../solver/solverClient.ts';
import type { QuadStructure } from '../structure.ts';

export const BAKER_OBJECTIVES = ['max-convex-edges', 'min-mixed-vertices'] as const satisfies readonly ObjectiveId[];
export type BakerObjective = (typeof BAKER_OBJECTIVES)[number];

export interface BakerState {
  structure: QuadStructure;
  objective: BakerObjective;
  epsilon: number;
  /** The library's run, once it has answered. */
  baker: BakerExplanation | null;
  layers: number;
  lambda: number | null;
  solution: Solution | null;
  failure: string | null;
}

/** Epsilon as the view takes it: within [0.05, 0.95], 0.34 if not a number. */
export const clampEpsilon = (text: string) => Math.min(0.95, Math.max(0.05, Number(text) || 0.34));

export const startRun = (structure: QuadStructure, objective: BakerObjective, epsilon: number): BakerState => ({
  structure,
  objective,
  epsilon,
  baker: null,
  layers: 0,
  lambda: null,
  solution: null,
  failure: null,
});

/** The run with the library's answer. */
export function withOutcome(s: BakerState, o: SolveOutcome): BakerState {
  if (o.status !== 'solved') return { ...s, failure: o.status === 'failed' ? o.message : 'cancelled' };
  const baker = o.explanation?.baker ?? null;
  if (!baker) return { ...s, solution: o.solution, failure: `the library did not run Baker's scheme (${o.solution.details})` };
  return { ...s, solution: o.solution, baker, lambda: baker.lambda, layers: baker.layer.reduce((a, b) => Math.max(a, b + 1), 0) };
}

export const shiftsOf = (s: BakerState) => s.baker?.shifts ?? [];
export const lastPosition = (s: BakerState | null) => (s?.lambda ? s.lambda + 1 : 0);
/** The shift shown at a position, or null (the layers, the result). */
export const shiftAt = (s: BakerState, pos: number): number | null => (s.lambda && pos >= 1 && pos <= s.lambda ? pos - 1 : null);

/** Does a cut of this shift (after the layers l with l mod lambda == shift)
 * separate two quads in layers lo <= hi? (Drawing only: the library decided
 * which terms each shift dropped.) */
export function isCut(lo: number, hi: number, shift: number, lambda: number): boolean {
  const firstCut = lo + ((((shift - lo) % lambda) + lambda) % lambda);
  return firstCut < hi;
}

/** The layers l after which a shift cuts (l | l + 1), within the terrain's layers. */
export function cutsOf(shift: number, layers: number, lambda: number): number[] {
  const cuts: number[] = [];
  for (let l = shift; l < layers - 1; l += lambda) cuts.push(l);
  return cuts;
}

/** Most convex edges: the best value is the largest, the bound the smallest;
 * fewest mixed vertices the other way round. */
export const isMax = (s: BakerState) => s.objective === 'max-convex-edges';
export const pick = (values: number[], most: boolean) => (most ? Math.max(...values) : Math.min(...values));
export const bestValue = (s: BakerState) => pick(shiftsOf(s).map((x) => x.value), isMax(s));
export const tightestBound = (s: BakerState) => pick(shiftsOf(s).map((x) => x.bound), !isMax(s));
/** The first shift with the best value, or null before the library answered. */
export function bestShift(s: BakerState): BakerExplanation['shifts'][number] | null {
  const shifts = shiftsOf(s);
  const max = isMax(s);
  return shifts.length ? shifts.reduce((a, b) => ((max ? b.value > a.value : b.value < a.value) ? b : a)) : null;
}

/** The diagonals drawn at a position: a shift's triangulation, the result's, or none. */
export function choiceAt(s: BakerState, pos: number): Uint8Array | null {
  const shift = shiftAt(s, pos);
  return shift !== null ? (shiftsOf(s)[shift]?.choice ?? null) : pos > 0 && s.solution ? s.solution.choice : null;
}

export function counterText(s: BakerState, pos: number): string {
  return !s.lambda ? '' : pos === 0 ? 'layers' : pos > s.lambda ? 'result' : `shift ${pos - 1} of 0–${s.lambda - 1}`;
}

export function captionText(s: BakerState, pos: number): string {
  return !s.lambda || pos === 0
    ? 'Quads by layer (peeling depth), joined when they share an edge'
    : pos > s.lambda
      ? 'The library’s result: flipped quads outlined amber'
      : `Shift ${pos - 1}: red dashes are cut · amber outlines: this shift’s flips`;
}

export function bakerHooks(s: BakerState | null, objective: string, pos: number): Record<string, unknown> {
  return {
    objective,
    epsilon: s?.epsilon ?? null,
    lambda: s?.lambda ?? null,
    layers: s?.layers ?? 0,
    position: pos,
    atEnd: s !== null && s.lambda !== null && pos === lastPosition(s),
    // In the objective's units (mixed vertices: value and lower bound).
    shifts: s ? shiftsOf(s).map((x) => ({ shift: x.shift, cut: x.dropped, relaxed: x.relaxed, value: x.value, bound: x.bound })) : [],
    library: s?.solution ? { value: s.solution.value, bound: s.solution.bound, details: s.solution.details } : null,
    failure: s?.failure ?? null,
  };
}
