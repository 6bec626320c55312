// The Mixed vertices view (the paper's Section 3.1): the NP-hardness
// construction for the fewest mixed vertices, built from a small formula, solved
// exactly by the library and checked.
import { VertexClass } from 'hodt';
import { h } from '../../ui/dom.ts';
import { CATEGORICAL, createFittedCanvas } from '../canvas.ts';
import { legend, paperLink } from '../common.ts';
import { FormulaError } from '../formula.ts';
import { gadgetHooks, gadgetRunner, valuesText } from '../gadgetModel.ts';
import { checkSpan, createGadgetPane, fillClauseTable, formulaLine, gadgetTab, showUnbuilt, solverLine } from '../gadgetPane.ts';
import { teachView } from '../view.ts';
import { MixedLayoutError } from './build.ts';
import { readMixedAssignment } from './check.ts';
import { drawMixed, MIXED } from './draw.ts';
import { DEFAULT_MIXED_FORMULA, judgeMixed, makeMixed, MAX_VARIABLES, mixedHooks, mixedJob, type MixedBuilt } from './model.ts';

export const mixedView = teachView({
  id: 'mixed',
  label: 'Mixed vertices',
  create(ctx) {
    const { root, side, main, caption, input, summary, verdict } = createGadgetPane({
      id: 'mixed',
      title: 'Why the fewest mixed vertices is NP-hard',
      label: `Formula (clauses of one to three literals, up to ${MAX_VARIABLES} variables)`,
      formula: DEFAULT_MIXED_FORMULA,
      rows: 2,
      ariaLabel: 'Formula for the mixed vertices gadget',
      buildTitle: 'Build the gadget for this formula and solve it exactly (fewest mixed vertices)',
      run: () => runner.run(),
      lead: [
        'Each variable is a fan: a ring of 6 flippable quads on a hexagonal grid. An inner point is mixed exactly when both quads beside it use the diagonal that reaches it, so a fan free of mixed points turns all one way, clockwise or counterclockwise: the variable’s two values. ',
        'A clause is a corner where its variables’ fans meet, mixed exactly when the diagonals of all its false literals reach it. The centre points are always mixed, so the fewest mixed vertices is that floor exactly when the formula is satisfiable. See ',
        paperLink('3.1'),
        '.',
      ],
    });
    const clauses = h('table', { class: 'teach-table', id: 'mixed-clauses' });
    const honesty = h(
      'p',
      { class: 'teach-note' },
      h('b', {}, 'What this page does not show. '),
      'Each variable is one fan, so the formula must fit on the grid: the fans of every clause must meet at a corner of their own (a search places them, or the page says why it cannot), two three-literal clauses cannot share all three variables, and a one-literal clause needs a corner no other fan touches. Around a corner the fans’ counterclockwise diagonals are 120 degrees apart, so a three-literal clause needs its false literals’ fans to turn the same way and a two-literal one opposite ways: a formula whose clauses ask a fan for both is refused (the paper’s inverter gadgets and fan chains, which split a variable over many fans, are not built). The coordinates and heights are this page’s own: every instance is checked above, not assumed.',
    );
    side.append(
      verdict,
      summary,
      clauses,
      legend([
        ['fill', CATEGORICAL[0]!, 'a variable’s fan (one colour per variable)'],
        ['line', '#111', 'the diagonal each quad uses in the solver’s optimum'],
        ['dot', MIXED, 'a mixed vertex of the optimum (the centres always are)'],
        ['dot', '#17804a', 'clause vertex, not mixed'],
        ['dot', 'rgba(90, 100, 96, 0.6)', 'other points (heights alternate around the rings)'],
      ]),
      honesty,
    );
    const canvas = createFittedCanvas(main, (c, f) => runner.built && drawMixed(c, f, runner.built), 'The mixed vertices gadget: fans, clause vertices and the diagonals of the optimum');

    const runner = gadgetRunner<MixedBuilt>(ctx, {
      text: () => input.value,
      refusals: [FormulaError, MixedLayoutError],
      make: (text) => makeMixed(ctx.hodt, text),
      built: (b) => canvas.fit(b.gadget.points, 18),
      job: mixedJob,
      render: () => render(),
    });

    function render(): void {
      canvas.redraw();
      const b = runner.built;
      caption.textContent = b?.solution ? 'The exact optimum: each quad’s diagonal; mixed vertices in red' : 'The construction';
      if (!b) {
        showUnbuilt(summary, runner.error, verdict, clauses);
        return;
      }
      const f = b.formula;
      const g = b.gadget;
      summary.replaceChildren(
        ...formulaLine('mixed', f, b.satisfying !== null),
        `The gadget: ${(g.points.length / 3).toLocaleString('en')} points, ${b.terrain.numQuads} flippable quads (${g.fans.length * 6} in fans, the others in the filling), floor ${g.floor}. `,
        solverLine(b, (v) => `${v} mixed vertices at fewest`),
      );
      const read = b.solution ? readMixedAssignment(g, b.map, b.solution.choice) : null;
      const classes = b.solution ? b.terrain.measures(b.solution.choice).vertexClass : null;
      fillClauseTable(clauses, f, g.clauses, read?.assignment ?? null, classes ? (p) => (classes[p] === VertexClass.Mixed ? 'mixed' : 'not mixed') : null, {
        satisfied: 'by the values read from the fans of the optimum',
        vertex: 'the clause vertex in the optimum',
      });
      const j = judgeMixed(b);
      verdict.replaceChildren();
      if (j.holds === null) return;
      if (read) {
        const impure = f.names.filter((_, v) => read.disagreeing[v]! > 0);
        verdict.append(
          valuesText(f, 'fans', read.assignment),
          impure.length ? ` (by most of their quads: the fan${impure.length === 1 ? '' : 's'} of ${impure.join(', ')} turn${impure.length === 1 ? 's' : ''} both ways, which costs a mixed vertex). ` : '. ',
        );
      }
      verdict.append(checkSpan('mixed', j));
    }

    return gadgetTab({ root, runner, canvas, hooks: gadgetHooks(runner, () => input.value, judgeMixed, mixedHooks) });
  },
});
