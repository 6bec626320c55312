// The Hardness gadget view (the paper's Section 3.3): the NP-hardness
// construction for the most convex edges, built from a MAX-2-SAT formula,
// solved by the library and read back.
import { h } from '../../ui/dom.ts';
import { EDGE_COLORS } from '../../views/palette.ts';
import { variableColor } from '../canvas.ts';
import { button } from '../common.ts';
import { clauseTrue, countSatisfied, formatClause, FormulaError } from '../formula.ts';
import { createGadgetView, type GadgetPanels } from '../gadgetPane.ts';
import { teachView } from '../view.ts';
import { LayoutError } from './build.ts';
import { drawGadget } from './draw.ts';
import { certifySlice, DEFAULT_FORMULA, gadgetJob, gadgetViewHooks, isExact, makeGadget, readSolved, type GadgetBuilt } from './model.ts';

export const gadgetView = teachView({
  id: 'gadget',
  label: 'Hardness gadget',
  create(ctx) {
    const open = button('gadget-open', 'Open in the main views', 'Load the gadget’s points into the page (objective: most convex edges)', () => {
      const built = runner.built;
      if (!built) return;
      ctx.load(built.gadget.points, 'load the hardness gadget', 'max-convex-edges');
      ctx.showViews();
    });
    const vars = h('table', { class: 'teach-table', id: 'gadget-vars' });
    const clauses = h('table', { class: 'teach-table', id: 'gadget-clauses' });
    const { view, runner, render } = createGadgetView(ctx, {
      id: 'gadget',
      title: 'Why most convex edges is NP-hard',
      lead: [
        'A grid of unit quads with heights f(x, y) = xy − (x² + y²)/10 has one convex (red) and one reflex (blue) diagonal in every quad, and an edge between two quads is convex unless both use their convex diagonal. ',
        'So a large pool of quads scores best in one of two chessboard patterns: a variable. Each clause sends a tentacle from each of its two pools; they meet at one shared edge, which scores when either end quad is reflex, that is when either literal is true. ',
        'High points coat everything else. The best triangulation then satisfies as many clauses as possible: MAX-2-SAT. ',
      ],
      section: '3.3',
      formula: { label: 'Formula (clauses of two literals, up to 10 variables)', text: DEFAULT_FORMULA, rows: 3, ariaLabel: 'MAX-2-SAT formula' },
      buildTitle: 'Build the gadget for this formula and solve it',
      buttons: [open],
      panels: ({ summary, verdict }) => [summary, verdict, vars, clauses],
      legend: [
        ['fill', variableColor(0), 'a variable’s pool and its tentacles (one colour per variable)'],
        ['line', EDGE_COLORS.convex, 'a quad using its convex diagonal'],
        ['line', EDGE_COLORS.reflex, 'a quad using its reflex diagonal'],
        ['dash', '#111', 'a tentacle cell that skips a column'],
        ['line', '#17804a', 'clause edge that scores (its clause is satisfied); grey: it does not'],
        ['dot', 'rgba(90, 100, 96, 0.6)', 'coating points (high, they fix everything else)'],
      ],
      note: [
        [
          'Not a proof. ',
          'The paper proves the reduction for planar formulas with pools larger than their number of tentacles. Here pools are at most 8 quads high (so the exact solver can handle them), and the tentacles turn corners and skip columns in ways the paper only sketches, so this page does not claim the construction is exact in general: it checks every instance instead (the check above), by scoring the chessboard pattern of all 2ⁿ assignments.',
        ],
      ],
      canvas: {
        draw: drawGadget,
        label: 'The hardness gadget: variable pools, tentacles and clause edges',
        fit: ({ gadget: { bounds: { x0, y0, x1, y1 } } }) => Float64Array.of(x0, y0, 0, x1, y1, 0),
        margin: 12,
      },
      make: makeGadget,
      refusals: [FormulaError, LayoutError],
      job: gadgetJob,
      solved(b) {
        if (!b.solution) return;
        readSolved(b);
        certifyInSlices(b);
      },
      solvedCaption: 'Optimum: red convex, blue reflex diagonals · green clause edge convex · dashed: a skipped column',
      unbuilt: [vars, clauses],
      show,
      hooks: (r, formula) => gadgetViewHooks(r.error, formula, r.built),
    });

    /** Scores the pattern of every assignment, 32 per task. */
    function certifyInSlices(b: GadgetBuilt): void {
      const values: number[] = [];
      const step = () => {
        if (!runner.current(b)) return;
        const more = certifySlice(b, values, 32);
        render();
        if (more) window.setTimeout(step, 0);
      };
      window.setTimeout(step, 0);
    }

    /** The built gadget: its summary, the pools' values, the clause edges, the check. */
    function show(b: GadgetBuilt, { summary, verdict }: GadgetPanels): void {
      const f = b.formula;
      const g = b.gadget;
      const n = f.names.length;
      summary.replaceChildren(
        `${n} variable${n === 1 ? '' : 's'}, ${f.clauses.length} clause${f.clauses.length === 1 ? '' : 's'}. `,
        'Best possible (all 2',
        h('sup', {}, String(n)),
        ' assignments tried): ',
        h('b', { id: 'gadget-optimum', 'data-value': String(b.optimum.best) }, `${b.optimum.best} of ${f.clauses.length}`),
        ` clauses. The gadget: ${(g.points.length / 3).toLocaleString('en')} points, ${b.terrain.numQuads.toLocaleString('en')} flippable quads (${g.cells.length} in pools and tentacles). `,
        b.solution
          ? `The library (${b.solution.method}${b.solution.optimal ? ', proven optimal' : ', not proven optimal'}) finds ${b.solution.value} convex edges in ${b.solution.timeMs.toFixed(0)} ms.`
          : b.failure
            ? h('span', { class: 'error' }, `The library could not solve it: ${b.failure}.`)
            : 'Solving…',
      );
      const rb = b.readback;
      vars.replaceChildren(
        h('thead', {}, h('tr', {}, h('th', {}, 'variable'), h('th', {}, 'pool phase → value'), h('th', { title: 'share of the pool in that chessboard phase' }, 'clean'))),
        h(
          'tbody',
          {},
          ...g.order.map((v) =>
            h(
              'tr',
              { 'data-variable': f.names[v]! },
              h('td', {}, h('i', { class: 'swatch', style: `background: ${variableColor(v)}` }), f.names[v]!),
              h('td', {}, rb ? h('b', { class: rb.assignment[v] ? 'good' : 'bad' }, rb.assignment[v] ? 'true' : 'false') : '…'),
              h('td', {}, rb ? `${Math.round(rb.agreement[v]! * 100)}%` : ''),
            ),
          ),
        ),
      );
      clauses.replaceChildren(
        h('thead', {}, h('tr', {}, h('th', {}, '#'), h('th', {}, 'clause'), h('th', { title: 'by the assignment read from the pools' }, 'satisfied'), h('th', { title: 'the meeting edge of its tentacles in the solver’s triangulation' }, 'edge'))),
        h(
          'tbody',
          {},
          ...f.clauses.map((c, k) =>
            h(
              'tr',
              {},
              h('td', {}, String(k + 1)),
              h('td', {}, formatClause(f, c)),
              h('td', {}, rb ? (clauseTrue(c, rb.assignment) ? '✓' : '✗') : ''),
              h('td', { title: rb && rb.edgeConvex[k] && !clauseTrue(c, rb.assignment) ? `convex although the clause is false: ${rb.defects[k]} quad(s) of its tentacles leave the chessboard pattern, which costs what the edge earns` : '' }, rb ? (rb.edgeConvex[k] ? (clauseTrue(c, rb.assignment) ? 'convex' : 'convex*') : 'reflex') : ''),
            ),
          ),
        ),
      );
      if (!rb) {
        verdict.replaceChildren();
        return;
      }
      const ties = f.clauses.filter((c, k) => rb.edgeConvex[k] && !clauseTrue(c, rb.assignment)).length;
      if (ties) {
        clauses.append(
          h('caption', {}, `* convex although the clause is false: a tentacle leaves the chessboard pattern there, which costs as much as the edge earns (a tie, so the optimum's value still counts ${b.optimum.best} clauses).`),
        );
      }
      const satisfied = countSatisfied(f, rb.assignment);
      const ok = satisfied === b.optimum.best;
      const parts: (string | Node)[] = [
        h(
          'b',
          { id: 'gadget-satisfied', 'data-value': String(satisfied), class: ok ? 'good' : 'bad' },
          `The assignment read from the pools satisfies ${satisfied} of ${f.clauses.length} clauses`,
        ),
        ok ? ': the formula’s optimum. ' : `, below the optimum ${b.optimum.best}. `,
      ];
      const cert = b.certificate;
      if (!cert) parts.push(`Checking the construction: ${b.checked} of ${1 << n} assignments scored…`);
      else if (cert.constant === null) parts.push(h('span', { class: 'bad', id: 'gadget-check', 'data-ok': 'false' }, 'Check failed: the patterns of the assignments do not score a constant plus their satisfied clauses, so this instance is not exact.'));
      else {
        const exact = isExact(b, cert);
        parts.push(
          h(
            'span',
            { id: 'gadget-check', 'data-ok': String(exact), class: exact ? '' : 'bad' },
            `Check: the chessboard pattern of each of the ${cert.tried} assignments scores ${cert.constant} + (its satisfied clauses) convex edges, `,
            exact
              ? `and the proven optimum is ${b.solution!.value} = ${cert.constant} + ${b.optimum.best}: on this instance the reduction is exact.`
              : `but the solver’s value ${b.solution!.value} is not ${cert.constant} + ${b.optimum.best}${b.solution!.optimal ? '' : ' (and it is not proven optimal)'}: this instance is not verified.`,
          ),
        );
      }
      verdict.replaceChildren(...parts);
    }

    return view;
  },
});
