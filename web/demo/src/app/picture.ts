// What the 3D and plan views draw, as Analysis values computed from the state:
// the committed terrain with a solution or Delaunay, or a drag's preview.
import type { Solution } from 'hodt';
import { analyse, analyseTriangles, type Analysis } from './analysis.ts';
import type { AppState, BuiltTerrain } from './appState.ts';

/** The committed terrain with a choice (null: Delaunay, all zeros). */
export function choicePicture(s: Pick<AppState, 'committed' | 'points'>, choice: Uint8Array | null, critical: Solution['critical'] = null): Analysis {
  const { terrain, structure } = s.committed;
  return analyse(terrain, structure, s.points, choice ?? new Uint8Array(structure.quads.length / 4), critical);
}

/** The committed terrain with a solution: a choice of diagonals (order 1) or,
 * at order k >= 2, its triangles. */
export function solutionPicture(s: Pick<AppState, 'committed' | 'points'>, solution: Solution): Analysis {
  if (solution.order > 1) return analyseTriangles(s.committed.terrain, s.committed.structure, s.points, solution.triangles);
  return choicePicture(s, solution.choice, solution.critical);
}

/** What was committed: the solution if there is one, else Delaunay. */
export function committedPicture(s: Pick<AppState, 'committed' | 'points' | 'solution'>): Analysis {
  return s.solution ? solutionPicture(s, s.solution) : choicePicture(s, null);
}

/** A drag's preview terrain, Delaunay (a live edit has no solution yet). */
export function previewPicture(preview: BuiltTerrain, points: Float64Array): Analysis {
  return analyse(preview.terrain, preview.structure, points, new Uint8Array(preview.structure.quads.length / 4));
}
