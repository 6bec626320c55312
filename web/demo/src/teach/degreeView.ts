// Teaching view: the NP-hardness construction of Section 3.2 (lowest maximum
// degree), built from a small formula, solved exactly by the library and checked.
import { h } from '../ui/dom.ts';
import { CATEGORICAL, createFittedCanvas, drawQuad, tint, type FittedCanvas } from './canvas.ts';
import { legend, paperLink, type TeachContext, type TeachView } from './common.ts';
import {
  checkSpan,
  createGadgetPane,
  fillClauseTable,
  formulaLine,
  gadgetHooks,
  gadgetRunner,
  gadgetTab,
  judgeReduction,
  parseGadgetFormula,
  showUnbuilt,
  solverLine,
  valuesText,
  type BuiltFormulaGadget,
  type Verdict,
} from './gadgetPane.ts';
import { FormulaError, satisfyingAssignment } from './formula.ts';
import { buildDegreeGadget, DegreeLayoutError, type DegreeGadget } from './degreeGadget.ts';
import { certifyDegree, mapDegreeCells, readDegreeAssignment, type DegreeCells, type DegreeCertificate } from './degreeCheck.ts';

export const DEFAULT_DEGREE_FORMULA = 'x | y, !y | z, !x';

const MAX_VARIABLES = 6;

type Built = BuiltFormulaGadget<DegreeGadget, DegreeCells, DegreeCertificate>;


export function createDegreeView(ctx: TeachContext): TeachView {
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
  const canvas = createFittedCanvas(main, (c, f) => draw(c, f), 'The maximum degree gadget: rows of cells, clause vertices and their fixed neighbours');

  const runner = gadgetRunner<Built>(ctx, {
    text: () => input.value,
    refusals: [FormulaError, DegreeLayoutError],
    make(text) {
      const formula = parseGadgetFormula(text, 2, 'x | y, !x', MAX_VARIABLES);
      const gadget = buildDegreeGadget(formula);
      const terrain = ctx.hodt.terrain(gadget.points, { maxEdge: gadget.maxEdge });
      const map = mapDegreeCells(gadget, terrain.quads);
      const certificate = certifyDegree(gadget, map, terrain.numQuads, (c) => terrain.evaluate(c)['minmax-degree']);
      return { formula, gadget, terrain, map, satisfying: satisfyingAssignment(formula), certificate, solution: null, failure: null };
    },
    built: (b) => canvas.fit(b.gadget.points, 16),
    job: (b) => ({ points: b.gadget.points, objective: 'minmax-degree', method: 'exact', epsilon: 0.1, order: 1, maxEdge: b.gadget.maxEdge }),
    render: () => render(),
  });

  /** Does the reduction hold on this instance, and if not, where does it fail? */
  function judge(b: Built): Verdict {
    const d = b.gadget.bound;
    const sat = b.satisfying !== null;
    const wrong = b.certificate.wrong.length;
    return judgeReduction(b.solution, (s) => ({
      per:
        wrong === 0
          ? `each of the ${b.certificate.values.length} assignments’ triangulations has maximum degree at most ${d} exactly when the assignment satisfies the formula, and `
          : `${wrong} assignment(s) break “maximum degree at most ${d} exactly when satisfied”, and `,
      holds: (s.value <= d) === sat && wrong === 0,
      found: sat ? `≤ d = ${d}, and the formula is satisfiable` : `> d = ${d}, and the formula is unsatisfiable`,
      missed: ` while the formula is ${sat ? 'satisfiable' : 'unsatisfiable'}`,
    }));
  }

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
    const j = judge(b);
    verdict.replaceChildren();
    if (j.holds === null) return;
    if (read) {
      verdict.append(`${valuesText(f, 'rows', read.assignment)}. `);
    }
    verdict.append(checkSpan('degree', j));
  }

  function draw(c: CanvasRenderingContext2D, fc: FittedCanvas): void {
    const b = runner.built;
    if (!b) return;
    const g = b.gadget;
    const p = g.points;
    const X = (i: number) => fc.sx(p[3 * i]!);
    const Y = (i: number) => fc.sy(p[3 * i + 1]!);
    const choice = b.solution?.choice ?? null;
    const degrees = b.terrain.measures(choice ?? undefined).degree;
    g.cells.forEach((cell, i) => {
      const v = cell.wire >= 0 ? g.wires[cell.wire]!.variable : -1;
      const q = b.map.quad[i]!;
      const rises = (choice ? choice[q] === 0 : true) === (b.map.delaunayRises[i] === 1); // sw-ne
      drawQuad(c, X, Y, cell.corners, {
        fill: v >= 0 ? tint(CATEGORICAL[v % CATEGORICAL.length]!, 0.35) : 'rgba(120, 120, 120, 0.25)',
        outline: '#555',
        diagonalAC: rises,
        width: Math.max(1.5, fc.scale * 0.04),
      });
    });
    const r = Math.max(2, Math.min(5, fc.scale * 0.07));
    for (let i = 0; i < p.length / 3; i++) {
      const role = g.roles[i]!;
      const over = degrees[i]! > g.bound;
      c.fillStyle = over ? '#d62728' : role === 'clause' || role === 'unit' ? '#17804a' : role === 'pendant' ? 'rgba(90, 100, 96, 0.6)' : '#333';
      c.beginPath();
      c.arc(X(i), Y(i), role === 'pendant' && !over ? r * 0.6 : r, 0, 2 * Math.PI);
      c.fill();
    }
    c.font = `600 ${Math.max(10, Math.min(13, fc.scale * 0.22))}px system-ui, sans-serif`;
    c.textAlign = 'center';
    c.textBaseline = 'middle';
    for (const cv of g.clauses) {
      const i = cv.point;
      const up = p[3 * i + 1]! > 0.4 ? -1 : 1;
      c.fillStyle = degrees[i]! > g.bound ? '#d62728' : '#17804a';
      c.fillText(`C${cv.clause + 1}: ${degrees[i]}`, X(i), Y(i) + up * fc.scale * 0.28);
    }
    for (const w of g.wires) {
      const first = g.cells[w.cells[0]!]!, last = g.cells[w.cells.at(-1)!]!;
      c.fillStyle = CATEGORICAL[w.variable % CATEGORICAL.length]!;
      c.fillText(b.formula.names[w.variable]!, (fc.sx(first.x) + fc.sx(last.x + 1)) / 2, fc.sy(first.y + 1.55));
    }
  }

  return gadgetTab({
    id: 'degree',
    label: 'Max degree',
    root,
    runner,
    canvas,
    hooks: gadgetHooks(runner, input, judge, (b) => ({ maxEdge: b?.gadget.maxEdge ?? null, bound: b?.gadget.bound ?? null })),
  });
}

