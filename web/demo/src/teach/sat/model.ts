// The model of the 2-SAT search view (the paper's Section 2.1): the library's
// bottleneck search (terrain.explain) on the page's terrain, every threshold it
// tested with the quads it forced, its clauses, their strongly connected
// components and the assignment, and where the view's stepping is in it.
// Positions: 0 the start, 1 to n the n tests, n + 1 the end.
import type { ObjectiveId, SearchExplanation, Solution, Terrain, ThresholdTest } from 'hodt';
import { readStructure, type QuadStructure } from '../structure.ts';

export const PAIR_OBJECTIVES = [
  'minmax-edge-area-ratio',
  'minmax-edge-normal-angle',
  'minmax-edge-enclosing-circle',
  'minmax-vertex-area-ratio',
  'minmax-vertex-normal-angle',
] as const satisfies readonly ObjectiveId[];
export type PairObjective = (typeof PAIR_OBJECTIVES)[number];
export const isPairObjective = (id: string): id is PairObjective => (PAIR_OBJECTIVES as readonly string[]).includes(id);

export interface SatSearch {
  structure: QuadStructure;
  objective: PairObjective;
  search: SearchExplanation;
  solution: Solution;
  /** Index in search.candidates of each tested threshold. */
  rank: number[];
}

/** The view's state: the search, or why the library could not show one. */
export type SatState = { search: SatSearch; error: null } | { search: null; error: string | null };

export function explainSearch(terrain: Terrain, objective: PairObjective): SatState {
  try {
    const structure = readStructure(terrain);
    const { search, solution } = terrain.explain(objective);
    if (!search) throw new Error(`the library ran no threshold search for ${objective}`);
    const rank = search.tests.map((t) => search.candidates.indexOf(t.threshold));
    return { search: { structure, objective, search, solution, rank }, error: null };
  } catch (e) {
    return { search: null, error: e instanceof Error ? e.message : String(e) };
  }
}

export const lastPosition = (s: SatSearch | null) => (s ? s.search.tests.length + 1 : 0);

/** The test at a position, or null at the start and the end. */
export const testAt = (s: SatSearch, pos: number): ThresholdTest | null => (pos >= 1 && pos <= s.search.tests.length ? s.search.tests[pos - 1]! : null);

export function counterText(s: SatSearch, pos: number): string {
  const n = s.search.tests.length;
  return pos === 0 ? 'start' : pos > n ? 'done' : `step ${pos} of ${n}`;
}

export function captionText(s: SatSearch, pos: number, fmt: (v: number) => string): string {
  const t = testAt(s, pos);
  if (pos === 0) return 'Delaunay triangulation · flippable quads in pale teal';
  if (!t) return `Optimum: ${fmt(s.solution.value)} · flipped quads amber, worst pair pink`;
  return `Step ${pos}: t = ${fmt(t.threshold)} · ${t.satisfiable ? 'yes: the 2-SAT solution shown' : 'no'}`;
}

/** The diagonals drawn at a position: the optimum at the end, a satisfiable
 * test's assignment, else Delaunay's. */
export function choiceAt(s: SatSearch, pos: number): Uint8Array {
  if (pos > s.search.tests.length) return s.solution.choice;
  const t = testAt(s, pos);
  return t && t.assignment.length ? t.assignment : new Uint8Array(s.structure.m);
}

/** The pairs of distinct quads the test's clauses join, each once. */
export function quadPairs(t: ThresholdTest): [number, number][] {
  const seen = new Set<number>();
  const out: [number, number][] = [];
  for (let k = 0; k < t.clauses.length; k += 2) {
    const q = Math.min(t.clauses[k]! >> 1, t.clauses[k + 1]! >> 1), r = Math.max(t.clauses[k]! >> 1, t.clauses[k + 1]! >> 1);
    if (q === r || seen.has(q * 0x100000 + r)) continue;
    seen.add(q * 0x100000 + r);
    out.push([q, r]);
  }
  return out;
}

/** The binary search as the number line shows it: for each test, the candidates
 * still open before it (indices lo to hi), the candidate it tested and its answer. */
export function searchRows(s: SatSearch): { lo: number; hi: number; rank: number; satisfiable: boolean }[] {
  let lo = 0, hi = s.search.candidates.length - 1;
  return s.search.tests.map((t, i) => {
    const row = { lo, hi, rank: s.rank[i]!, satisfiable: t.satisfiable };
    if (t.satisfiable) hi = row.rank;
    else lo = row.rank + 1;
    return row;
  });
}

export function satHooks(s: SatState, objective: string, pos: number): Record<string, unknown> {
  const search = s.search;
  return {
    objective,
    steps: search ? search.search.tests.length : 0,
    position: pos,
    atEnd: search !== null && pos === lastPosition(search),
    value: search?.solution.value ?? null,
    tests: search?.search.tests.map((t) => ({ threshold: t.threshold, satisfiable: t.satisfiable, clauses: t.clauses.length / 2, conflicts: t.conflicts.length })) ?? [],
    error: s.error,
  };
}
