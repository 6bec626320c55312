/** The 13 objectives (docs/objectives.md). */
export const OBJECTIVE_IDS = [
  'max-convex-vertices',
  'minmax-edge-area-ratio',
  'minmax-edge-normal-angle',
  'minmax-edge-enclosing-circle',
  'minmax-vertex-area-ratio',
  'minmax-vertex-normal-angle',
  'min-local-minima',
  'min-local-extrema',
  'min-total-edge-length',
  'minmax-triangle-area',
  'max-convex-edges',
  'min-mixed-vertices',
  'minmax-degree',
] as const;

export type ObjectiveId = (typeof OBJECTIVE_IDS)[number];
/** What SolveOptions.method asks for. */
export type Method = 'brute-force' | 'exact' | 'approx' | 'auto';
/** What ran (Solution.method): 'auto' reports its choice; 'heuristic' is the
 * order k >= 2 local search with a proven bound. */
export type SolvedBy = 'brute-force' | 'exact' | 'approx' | 'heuristic';

export interface ObjectiveInfo {
  id: ObjectiveId;
  /** Whether the objective is minimised or maximised. */
  sense: 'min' | 'max';
  /** How its local terms make the value: their sum, or their largest (min-max). */
  combine: 'sum' | 'max';
  /** Counts and degrees are integers; ratios, angles and lengths are not. */
  integral: boolean;
  /** A polynomial exact algorithm at first order; false: NP-hard (exact by the factor graph engine where the instance allows, approximated with a proven bound otherwise). */
  polynomial: boolean;
  /** The unit of its value, e.g. `'ratio, >= 1'`, `'radians, 0 to pi'`, `'count'`. */
  unit: string;
  /** The result of the paper it rests on, e.g. `'Thm 3, 2-SAT'`. */
  reference: string;
  /** One sentence on what it optimises. */
  summary: string;
}

/** Values of all 13 objectives for one triangulation. */
export type ObjectiveValues = Record<ObjectiveId, number>;

export function toValues(array: Float64Array): ObjectiveValues {
  const out = {} as ObjectiveValues;
  OBJECTIVE_IDS.forEach((id, k) => (out[id] = array[k]!));
  return out;
}
