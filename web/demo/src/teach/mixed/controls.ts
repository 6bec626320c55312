// The Mixed vertices view (the paper's Section 3.1): the NP-hardness
// construction for the fewest mixed vertices, built from a small formula, solved
// exactly by the library and checked.
import { VertexClass } from 'hodt';
import { variableColor } from '../canvas.ts';
import { formulaGadgetView } from '../formulaGadgetView.ts';
import { drawMixed, MIXED } from './draw.ts';
import { DEFAULT_MIXED_FORMULA, mixedReduction } from './model.ts';

export const mixedView = formulaGadgetView(mixedReduction, {
  id: 'mixed',
  label: 'Mixed vertices',
  title: 'Why the fewest mixed vertices is NP-hard',
  lead: [
    'Each variable is a fan: a ring of 6 flippable quads on a hexagonal grid. An inner point is mixed exactly when both quads beside it use the diagonal that reaches it, so a fan free of mixed points turns all one way, clockwise or counterclockwise: the variable’s two values. ',
    'A clause is a corner where its variables’ fans meet, mixed exactly when the diagonals of all its false literals reach it. The centre points are always mixed, so the fewest mixed vertices is that floor exactly when the formula is satisfiable. ',
  ],
  section: '3.1',
  formula: { label: `Formula (clauses of one to three literals, up to ${mixedReduction.maxVariables} variables)`, text: DEFAULT_MIXED_FORMULA, rows: 2, ariaLabel: 'Formula for the mixed vertices gadget' },
  buildTitle: 'Build the gadget for this formula and solve it exactly (fewest mixed vertices)',
  legend: [
    ['fill', variableColor(0), 'a variable’s fan (one colour per variable)'],
    ['line', '#111', 'the diagonal each quad uses in the solver’s optimum'],
    ['dot', MIXED, 'a mixed vertex of the optimum (the centres always are)'],
    ['dot', '#17804a', 'clause vertex, not mixed'],
    ['dot', 'rgba(90, 100, 96, 0.6)', 'other points (heights alternate around the rings)'],
  ],
  note: [
    [
      'What this page does not show. ',
      'Each variable is one fan, so the formula must fit on the grid: the fans of every clause must meet at a corner of their own (a search places them, or the page says why it cannot), two three-literal clauses cannot share all three variables, and a one-literal clause needs a corner no other fan touches. Around a corner the fans’ counterclockwise diagonals are 120 degrees apart, so a three-literal clause needs its false literals’ fans to turn the same way and a two-literal one opposite ways: a formula whose clauses ask a fan for both is refused (the paper’s inverter gadgets and fan chains, which split a variable over many fans, are not built). The coordinates and heights are this page’s own: every instance is checked above, not assumed.',
    ],
  ],
  canvas: { draw: drawMixed, label: 'The mixed vertices gadget: fans, clause vertices and the diagonals of the optimum', margin: 18 },
  solvedCaption: 'The exact optimum: each quad’s diagonal; mixed vertices in red',
  gadget: ({ gadget: g, terrain }) => `The gadget: ${(g.points.length / 3).toLocaleString('en')} points, ${terrain.numQuads} flippable quads (${g.fans.length * 6} in fans, the others in the filling), floor ${g.floor}. `,
  finds: (v) => `${v} mixed vertices at fewest`,
  where: 'fans',
  after: ({ formula }, read) => {
    const impure = formula.names.filter((_, v) => read.disagreeing[v]! > 0);
    return impure.length ? ` (by most of their quads: the fan${impure.length === 1 ? '' : 's'} of ${impure.join(', ')} turn${impure.length === 1 ? 's' : ''} both ways, which costs a mixed vertex). ` : '. ';
  },
  vertex: {
    title: 'the clause vertex in the optimum',
    of: ({ terrain }, choice) => {
      const classes = terrain.measures(choice).vertexClass;
      return (p) => (classes[p] === VertexClass.Mixed ? 'mixed' : 'not mixed');
    },
  },
});
