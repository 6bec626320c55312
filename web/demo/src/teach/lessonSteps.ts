// The first lesson's steps: each opens a tab with a terrain made for it by one of
// the built-in seeded generators (so the link records it as {kind, count, seed}
// as well as its exact points), and says what that terrain shows. The seeds were
// chosen with the library for the claim each step makes, and tests/e2e/lesson.test.ts
// checks every claim against the library on the points the page loads.
import type { ObjectiveId } from 'hodt';
import type { TerrainSource } from '../ui/terrainPanel.ts';

export type LessonTab = 'brute' | 'sat' | 'baker' | 'gadget' | 'order' | 'water';

export interface LessonStep {
  tab: LessonTab;
  title: string;
  /** The step's terrain, or none (the view builds its own instance). */
  terrain?: TerrainSource;
  /** The sidebar's objective for the step (and epsilon, for the approximation). */
  objective?: ObjectiveId;
  epsilon?: number;
  /** The view's selects the step sets (by id, to an option's value), as if chosen. */
  controls?: Readonly<Record<string, string>>;
  /** The view's button the step presses, if any (one that builds its instance, or shows its layout). */
  build?: string;
  doThis: string;
  notice: string;
}

export const LESSON_STEPS: readonly LessonStep[] = [
  {
    tab: 'brute',
    title: 'All triangulations',
    // 14 random points, 7 flippable quads: 128 triangulations.
    terrain: { kind: 'uniform', count: 14, seed: 38 },
    objective: 'min-mixed-vertices',
    doThis: 'Look at the cards, then pick “Fewest pits” in the sidebar.',
    notice: 'Every first order triangulation is one choice of diagonal per teal quad: 2^m of them. On this terrain Delaunay (the card with no amber quad) is not the best for fewest mixed vertices, nor for fewest pits, and no triangulation is the best for both: the gold frames move when the objective changes.',
  },
  {
    tab: 'sat',
    title: '2-SAT search (Section 2.1)',
    terrain: { kind: 'grid', count: 64, seed: 15 },
    objective: 'minmax-edge-area-ratio',
    doThis: 'Press Play.',
    notice: 'Each test asks "can every pair stay below t?". Quads with one bad diagonal are forced; the rest become clauses. On this grid some tests answer no by a contradiction (a red ✕: both diagonals of a quad in one strongly connected component) and others yes; the search tests the lower bound first, then halves the candidates each time.',
  },
  {
    tab: 'baker',
    title: 'Baker’s layers (Section 4)',
    terrain: { kind: 'grid', count: 100, seed: 1 },
    objective: 'max-convex-edges',
    epsilon: 0.5,
    doThis: 'Step through the shifts at ε = 0.5, then choose ε = 0.25.',
    notice: 'Smaller ε means more layers per period (λ) and more shifts; every shift’s value is a real triangulation and its bound caps the optimum. On this grid ε = 0.25 narrows the gap that ε = 0.5 leaves: a proven gap, not a guess.',
  },
  {
    tab: 'gadget',
    title: 'Why most convex edges is NP-hard (Section 3.3)',
    build: 'gadget-build',
    doThis: 'Build the default formula, then change a clause and build again.',
    notice: 'The optimum minus a constant is the number of clauses the best assignment satisfies: solving this terrain solves MAX-2-SAT. The page checks this on every instance it builds.',
  },
  {
    tab: 'order',
    title: 'Higher order (Section 4.3)',
    terrain: { kind: 'uniform', count: 30, seed: 7 },
    objective: 'min-local-minima',
    doThis: 'Press Play to step k from 1 to 8.',
    notice: 'Regions cut by the fixed edges merge as k grows, each with more triangulations. On this terrain the fewest pits (red dots) falls from k = 1 to k = 2 and again to k = 3: pits that no first order triangulation removes go once a circumcircle may hold two points, then three.',
  },
  {
    tab: 'water',
    title: 'Why pits matter (Section 1)',
    // A fractal relief of 144 points whose Delaunay triangulation has pits that the
    // first and second order optima remove.
    terrain: { kind: 'fractal', count: 144, seed: 38 },
    objective: 'min-local-minima',
    controls: { 'water-objective': 'min-local-minima', 'water-order': '1' },
    build: 'water-show-both',
    doThis: 'Compare the two panes, then choose order 2.',
    notice: 'Water stops at every pit, so a pit the triangulation made up cuts its basin off from the stream it belongs to, and runoff and erosion models built on the terrain break there. On this terrain the fewest local minima at order 1 leaves fewer pits than Delaunay, and order 2 fewer still, with no new pit: the whole basin of each pit that went drains into one neighbour and takes its colour.',
  },
];
