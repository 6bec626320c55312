// Teaching view: the NP-hardness construction of Section 3.1 (fewest mixed
// vertices), built from a small formula, solved exactly by the library and checked.
import { VertexClass } from 'hodt';
import { h } from '../ui/dom.ts';
import { CATEGORICAL, createFittedCanvas, drawQuad, tint, type FittedCanvas } from './canvas.ts';
import { legend, paperLink, type TeachContext, type TeachView } from './common.ts';
import { FormulaError, satisfyingAssignment } from './formula.ts';
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
import { buildMixedGadget, MixedLayoutError, sectorCorners, type MixedGadget } from './mixedGadget.ts';
import { certifyMixed, mapFanSectors, readMixedAssignment, type FanSectors, type MixedCertificate } from './mixedCheck.ts';

export const DEFAULT_MIXED_FORMULA = 'x | y | z, !x | y, !y | w, !z';
const MAX_VARIABLES = 6;

type Built = BuiltFormulaGadget<MixedGadget, FanSectors, MixedCertificate>;

const MIXED = '#d62728';

export function createMixedView(ctx: TeachContext): TeachView {
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
  const canvas = createFittedCanvas(main, (c, f) => draw(c, f), 'The mixed vertices gadget: fans, clause vertices and the diagonals of the optimum');

  const runner = gadgetRunner<Built>(ctx, {
    text: () => input.value,
    refusals: [FormulaError, MixedLayoutError],
    make(text) {
      const formula = parseGadgetFormula(text, 3, 'x | y | z, !x', MAX_VARIABLES);
      const gadget = buildMixedGadget(formula);
      const terrain = ctx.hodt.terrain(gadget.points);
      const map = mapFanSectors(gadget, terrain.quads);
      const certificate = certifyMixed(gadget, map, terrain.numQuads, (c) => terrain.evaluate(c)['min-mixed-vertices']);
      return { formula, gadget, terrain, map, satisfying: satisfyingAssignment(formula), certificate, solution: null, failure: null };
    },
    built: (b) => canvas.fit(b.gadget.points, 18),
    job: (b) => ({ points: b.gadget.points, objective: 'min-mixed-vertices', method: 'exact', epsilon: 0.1, order: 1 }),
    render: () => render(),
  });

  /** Does the reduction hold on this instance, and if not, where does it fail? */
  function judge(b: Built): Verdict {
    const floor = b.gadget.floor;
    const sat = b.satisfying !== null;
    const wrong = b.certificate.wrong.length;
    return judgeReduction(b.solution, (s) => ({
      per:
        wrong === 0
          ? `each of the ${b.certificate.values.length} assignments’ triangulations has ${floor} + (its false clauses) mixed vertices, and `
          : `${wrong} assignment(s) do not have ${floor} + (their false clauses) mixed vertices, and `,
      holds: (s.value === floor) === sat && s.value >= floor && wrong === 0,
      found: sat ? `= ${floor}, the floor, and the formula is satisfiable` : `> ${floor}, the floor, and the formula is unsatisfiable`,
      missed: ` against a floor of ${floor} while the formula is ${sat ? 'satisfiable' : 'unsatisfiable'}`,
    }));
  }

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
    const j = judge(b);
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

  function draw(c: CanvasRenderingContext2D, fc: FittedCanvas): void {
    const b = runner.built;
    if (!b) return;
    const g = b.gadget;
    const p = g.points;
    const X = (i: number) => fc.sx(p[3 * i]!);
    const Y = (i: number) => fc.sy(p[3 * i + 1]!);
    const choice = b.solution?.choice ?? null;
    const classes = b.terrain.measures(choice ?? undefined).vertexClass;
    // Every edge of the triangulation, thin, then the fans' quads on top.
    const tri = b.terrain.triangulation(choice ?? undefined).triangles;
    c.strokeStyle = 'rgba(60, 72, 68, 0.25)';
    c.lineWidth = 0.7;
    c.beginPath();
    for (let k = 0; k < tri.length; k += 3) {
      c.moveTo(X(tri[k]!), Y(tri[k]!));
      c.lineTo(X(tri[k + 1]!), Y(tri[k + 1]!));
      c.lineTo(X(tri[k + 2]!), Y(tri[k + 2]!));
      c.closePath();
    }
    c.stroke();
    g.fans.forEach((fan, i) => {
      const colour = CATEGORICAL[fan.variable % CATEGORICAL.length]!;
      fan.inner.forEach((_, k) => {
        const q = b.map.quad[i]![k]!;
        const ccw = (choice ? choice[q] === 0 : true) === (b.map.delaunayCcw[i]![k] === 1);
        drawQuad(c, X, Y, sectorCorners(fan, k), { fill: tint(colour, 0.3), outline: '#777', diagonalAC: ccw, width: Math.max(1.5, fc.scale * 0.035) });
      });
    });
    const r = Math.max(2.2, Math.min(5, fc.scale * 0.07));
    for (let i = 0; i < p.length / 3; i++) {
      const role = g.roles[i]!;
      const mixed = classes[i] === VertexClass.Mixed;
      c.fillStyle = mixed ? MIXED : role === 'clause' || role === 'unit' ? '#17804a' : 'rgba(90, 100, 96, 0.6)';
      c.beginPath();
      c.arc(X(i), Y(i), mixed || role === 'clause' || role === 'unit' ? r : r * 0.7, 0, 2 * Math.PI);
      c.fill();
    }
    c.font = `600 ${Math.max(10, Math.min(13, fc.scale * 0.22))}px system-ui, sans-serif`;
    c.textAlign = 'center';
    c.textBaseline = 'middle';
    // Clause labels just below their vertex.
    const labelled = new Map<number, string[]>();
    for (const cv of g.clauses) labelled.set(cv.point, [...(labelled.get(cv.point) ?? []), `C${cv.clause + 1}`]);
    for (const [i, names] of labelled) {
      c.fillStyle = classes[i] === VertexClass.Mixed ? MIXED : '#17804a';
      c.fillText(names.join(', '), X(i), fc.sy(p[3 * i + 1]! - 0.45));
    }
    for (const fan of g.fans) {
      c.fillStyle = CATEGORICAL[fan.variable % CATEGORICAL.length]!;
      c.fillText(b.formula.names[fan.variable]!, fc.sx(fan.x), fc.sy(fan.y + 0.5));
    }
  }

  return gadgetTab({
    id: 'mixed',
    label: 'Mixed vertices',
    root,
    runner,
    canvas,
    hooks: gadgetHooks(runner, input, judge, (b) => ({
      floor: b?.gadget.floor ?? null,
      assignment: b?.solution ? readMixedAssignment(b.gadget, b.map, b.solution.choice).assignment : null,
    })),
  });
}
