// The Max degree view (the paper's Section 3.2): the NP-hardness construction
// for the lowest maximum degree, built from a small formula, solved exactly by
// the library and checked.
import { variableColor } from '../canvas.ts';
import { formulaGadgetView } from '../formulaGadgetView.ts';
import { drawDegree } from './draw.ts';
import { DEFAULT_DEGREE_FORMULA, degreeReduction } from './model.ts';

export const degreeView = formulaGadgetView(degreeReduction, {
  id: 'degree',
  label: 'Max degree',
  title: 'Why the lowest maximum degree is NP-hard',
  lead: [
    'Each cell below is a flippable quad, so it adds one to the degree of two opposite corners. A point on a side two cells share has d − 1 fixed neighbours: only one of the two diagonals that could reach it fits under d, so all cells of a row use the same diagonal, rising or falling: a variable. ',
    'Where two rows meet, the corner that both false literals’ diagonals would reach is a clause vertex: the two cannot both be there. A one-literal clause is a corner with d fixed neighbours. So the maximum degree can be at most d only if the formula is satisfiable. ',
  ],
  section: '3.2',
  formula: { label: `Formula (clauses of one or two literals, up to ${degreeReduction.maxVariables} variables)`, text: DEFAULT_DEGREE_FORMULA, rows: 2, ariaLabel: 'Formula for the maximum degree gadget' },
  buildTitle: 'Build the gadget for this formula and solve it exactly (lowest maximum degree)',
  legend: [
    ['fill', variableColor(0), 'a variable’s cells (one colour per variable); grey: a one-literal clause’s dummy cell'],
    ['line', '#111', 'the diagonal each cell uses in the solver’s optimum'],
    ['dot', '#17804a', 'clause vertex within d; red: a point over d'],
    ['dot', 'rgba(90, 100, 96, 0.6)', 'fixed neighbours (the paper’s Figure 9)'],
  ],
  note: [
    [
      'What this page does not show. ',
      'The rows are straight and have two ends, so it lays out chains only: clauses of one or two literals, every variable in at most two clauses, no cycle (two clauses on the same two variables only when one negates both literals of the other). The paper also splits rows (a ring of quads) and has clause vertices of three literals (d − 2 fixed neighbours); without them these formulas are ones 2-SAT solves, so this page shows how the gadgets work, not why the problem is hard. ',
    ],
    [
      'A domain. ',
      'The degrees are measured with a longest edge of 1.35 (a triangle with a longer edge is not measured): it leaves out the long triangles that fill the convex hull around the rows, which the paper triangulates with Ruppert’s algorithm instead. Every instance is checked above, not assumed.',
    ],
  ],
  canvas: { draw: drawDegree, label: 'The maximum degree gadget: rows of cells, clause vertices and their fixed neighbours', margin: 16 },
  solvedCaption: 'The exact optimum: each cell’s diagonal; points labelled with their degree where it matters',
  gadget: ({ gadget: g, terrain, map }) =>
    `The gadget: ${(g.points.length / 3).toLocaleString('en')} points, ${terrain.numQuads} flippable quads (${g.cells.length} cells; ${
      map.otherQuadsAtFixedPoints === 0
        ? 'the others lie in the filling, away from every point whose degree the construction fixes'
        : `${map.otherQuadsAtFixedPoints} others touch a point whose degree the construction fixes`
    }), d = ${g.bound}. `,
  finds: (v) => `a lowest maximum degree of ${v}`,
  where: 'rows',
  vertex: {
    title: 'degree of the clause vertex in the optimum',
    of: ({ terrain }, choice) => {
      const degrees = terrain.measures(choice).degree;
      return (p) => `degree ${degrees[p]}`;
    },
  },
});
