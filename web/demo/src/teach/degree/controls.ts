// The Max degree view (the paper's Section 3.2): the NP-hardness construction
// for the lowest maximum degree, built from a small formula, solved exactly by
// the library and checked.
import { h } from '../../ui/dom.ts';
import { CATEGORICAL, createFittedCanvas } from '../canvas.ts';
import { legend, paperLink } from '../common.ts';
import { FormulaError } from '../formula.ts';
import { gadgetHooks, gadgetRunner, valuesText } from '../gadgetModel.ts';
import { checkSpan, createGadgetPane, fillClauseTable, formulaLine, gadgetTab, showUnbuilt, solverLine } from '../gadgetPane.ts';
import { teachView } from '../view.ts';
import { DegreeLayoutError } from './build.ts';
import { readDegreeAssignment } from './check.ts';
import { drawDegree } from './draw.ts';
import { DEFAULT_DEGREE_FORMULA, degreeHooks, degreeJob, judgeDegree, makeDegree, MAX_VARIABLES, type DegreeBuilt } from './model.ts';

export const degreeView = teachView({
  id: 'degree',
  label: 'Max degree',
  create(ctx) {
    const { root, side, main, caption, input, summary, verdict } = createGadgetPane({ id: 'degree', title: 'Why the lowest maximum degree is NP-hard', label: `Formula (clauses of one or two literals, up to ${MAX_VARIABLES} variables)`, formula: DEFAULT_DEGREE_FORMULA, rows: 2, ariaLabel: 'Formula for the maximum degree gadget', buildTitle: 'Build the gadget for this formula and solve it exactly (lowest maximum degree)', run: () => runner.run(), lead: [
      'Each cell below is a flippable quad, so it adds one to the degree of two opposite corners. A point on a side two cells share has d − 1 fixed neighbours: only one of the two diagonals that could reach it fits under d, so all cells of a row use the same diagonal, rising or falling: a variable. ',
      'Where two rows meet, the corner that both false literals’ diagonals would reach is a clause vertex: the two cannot both be there. A one-literal clause is a corner with d fixed neighbours. So the maximum degree can be at most d only if the formula is satisfiable. See ',
      paperLink('3.2'),
      '.',
    ] });
    const clauses = h('table', { class: 'teach-table', id: 'degree-clauses' });
    const honesty = h(
      'p',
      { class: 'teach-note' },
      h('b', {}, 'What this page does not show. '),
      'The rows are straight and have two ends, so it lays out chains only: clauses of one or two literals, every variable in at most two clauses, no cycle (two clauses on the same two variables only when one negates both literals of the other). The paper also splits rows (a ring of quads) and has clause vertices of three literals (d − 2 fixed neighbours); without them these formulas are ones 2-SAT solves, so this page shows how the gadgets work, not why the problem is hard. ',
      h('b', {}, 'A domain. '),
      'The degrees are measured with a longest edge of 1.35 (a triangle with a longer edge is not measured): it leaves out the long triangles that fill the convex hull around the rows, which the paper triangulates with Ruppert’s algorithm instead. Every instance is checked above, not assumed.',
    );
    side.append(
      verdict,
      summary,
      clauses,
      legend([
        ['fill', CATEGORICAL[0]!, 'a variable’s cells (one colour per variable); grey: a one-literal clause’s dummy cell'],
        ['line', '#111', 'the diagonal each cell uses in the solver’s optimum'],
        ['dot', '#17804a', 'clause vertex within d; red: a point over d'],
        ['dot', 'rgba(90, 100, 96, 0.6)', 'fixed neighbours (the paper’s Figure 9)'],
      ]),
      honesty,
    );
    const canvas = createFittedCanvas(main, (c, f) => runner.built && drawDegree(c, f, runner.built), 'The maximum degree gadget: rows of cells, clause vertices and their fixed neighbours');

    const runner = gadgetRunner<DegreeBuilt>(ctx, {
      text: () => input.value,
      refusals: [FormulaError, DegreeLayoutError],
      make: (text) => makeDegree(ctx.hodt, text),
      built: (b) => canvas.fit(b.gadget.points, 16),
      job: degreeJob,
      render: () => render(),
    });

    function render(): void {
      canvas.redraw();
      caption.textContent = runner.built?.solution ? 'The exact optimum: each cell’s diagonal; points labelled with their degree where it matters' : 'The construction';
      const built = runner.built;
      if (!built) {
        showUnbuilt(summary, runner.error, verdict, clauses);
        return;
      }
      const b = built;
      const f = b.formula;
      const g = b.gadget;
      summary.replaceChildren(
        ...formulaLine('degree', f, b.satisfying !== null),
        `The gadget: ${(g.points.length / 3).toLocaleString('en')} points, ${b.terrain.numQuads} flippable quads (${g.cells.length} cells; ${
          b.map.otherQuadsAtFixedPoints === 0
            ? 'the others lie in the filling, away from every point whose degree the construction fixes'
            : `${b.map.otherQuadsAtFixedPoints} others touch a point whose degree the construction fixes`
        }), d = ${g.bound}. `,
        solverLine(b, (v) => `a lowest maximum degree of ${v}`),
      );
      const read = b.solution ? readDegreeAssignment(g, b.map, b.solution.choice) : null;
      const degrees = b.solution ? b.terrain.measures(b.solution.choice).degree : null;
      fillClauseTable(clauses, f, g.clauses, read?.assignment ?? null, degrees ? (p) => `degree ${degrees[p]}` : null, {
        satisfied: 'by the values read from the rows of the optimum',
        vertex: 'degree of the clause vertex in the optimum',
      });
      const j = judgeDegree(b);
      verdict.replaceChildren();
      if (j.holds === null) return;
      if (read) {
        verdict.append(`${valuesText(f, 'rows', read.assignment)}. `);
      }
      verdict.append(checkSpan('degree', j));
    }

    return gadgetTab({ root, runner, canvas, hooks: gadgetHooks(runner, () => input.value, judgeDegree, degreeHooks) });
  },
});
