// Teaching view 3: the NP-hardness construction of Section 3.3, built from a
// MAX-2-SAT formula, solved by the library (most convex edges) and read back.
import type { Solution, Terrain } from 'hodt';
import { h } from '../ui/dom.ts';
import { EDGE_COLORS } from '../views/palette.ts';
import { CATEGORICAL, createFittedCanvas, tint, type FittedCanvas } from './canvas.ts';
import { button, legend, paperLink, type TeachContext, type TeachView } from './common.ts';
import { createGadgetPane, gadgetRunner, showUnbuilt } from './gadgetPane.ts';
import { clauseTrue, countSatisfied, formatClause, FormulaError, maxSatisfiable, parseFormula, type Formula } from './formula.ts';
import { buildGadget, LayoutError, type Gadget } from './gadget.ts';
import { canonicalStates, cellStates, choiceFor, mapCells, readBack, type CellQuads, type GadgetCertificate, type Readback } from './gadgetCheck.ts';

export const DEFAULT_FORMULA = 'x1 | x2, !x1 | x2, x1 | !x2, !x1 | !x2, x2 | x3, !x3 | x1';

interface Built {
  formula: Formula;
  gadget: Gadget;
  terrain: Terrain;
  map: CellQuads;
  optimum: ReturnType<typeof maxSatisfiable>;
  solution: Solution | null;
  failure: string | null;
  readback: Readback | null;
  certificate: GadgetCertificate | null;
  /** Assignments certified so far (the check runs in slices). */
  checked: number;
}

export function createGadgetView(ctx: TeachContext): TeachView {
  const { root, side, main, caption, input, build, buttons, summary, verdict } = createGadgetPane({ id: 'gadget', title: 'Why most convex edges is NP-hard', label: 'Formula (clauses of two literals, up to 10 variables)', formula: DEFAULT_FORMULA, rows: 3, ariaLabel: 'MAX-2-SAT formula', buildTitle: 'Build the gadget for this formula and solve it', run: () => runner.run(), lead: [
    'A grid of unit quads with heights f(x, y) = xy − (x² + y²)/10 has one convex (red) and one reflex (blue) diagonal in every quad, and an edge between two quads is convex unless both use their convex diagonal. ',
    'So a large pool of quads scores best in one of two chessboard patterns: a variable. Each clause sends a tentacle from each of its two pools; they meet at one shared edge, which scores when either end quad is reflex, that is when either literal is true. ',
    'High points coat everything else. The best triangulation then satisfies as many clauses as possible: MAX-2-SAT. See ',
    paperLink('3.3'),
    '.',
  ] });
  const open = button('gadget-open', 'Open in the main views', 'Load the gadget’s points into the page (objective: most convex edges)', () => {
    const built = runner.built;
    if (!built) return;
    ctx.load(built.gadget.points, 'load the hardness gadget', 'max-convex-edges');
    ctx.showViews();
  });
  const vars = h('table', { class: 'teach-table', id: 'gadget-vars' });
  const clauses = h('table', { class: 'teach-table', id: 'gadget-clauses' });
  const honesty = h(
    'p',
    { class: 'teach-note' },
    h('b', {}, 'Not a proof. '),
    'The paper proves the reduction for planar formulas with pools larger than their number of tentacles. Here pools are at most 8 quads high (so the exact solver can handle them), and the tentacles turn corners and skip columns in ways the paper only sketches, so this page does not claim the construction is exact in general: it checks every instance instead (the check above), by scoring the chessboard pattern of all 2ⁿ assignments.',
  );
  buttons.append(open);
  side.append(
    summary,
    verdict,
    vars,
    clauses,
    legend([
      ['fill', CATEGORICAL[0]!, 'a variable’s pool and its tentacles (one colour per variable)'],
      ['line', EDGE_COLORS.convex, 'a quad using its convex diagonal'],
      ['line', EDGE_COLORS.reflex, 'a quad using its reflex diagonal'],
      ['dash', '#111', 'a tentacle cell that skips a column'],
      ['line', '#17804a', 'clause edge that scores (its clause is satisfied); grey: it does not'],
      ['dot', 'rgba(90, 100, 96, 0.6)', 'coating points (high, they fix everything else)'],
    ]),
    honesty,
  );
  const canvas = createFittedCanvas(main, (c, f) => draw(c, f), 'The hardness gadget: variable pools, tentacles and clause edges');

  let active = false;
  const runner = gadgetRunner<Built>(ctx, {
    text: () => input.value,
    refusals: [FormulaError, LayoutError],
    make(text) {
      const formula = parseFormula(text);
      const gadget = buildGadget(formula);
      const terrain = ctx.hodt.terrain(gadget.points);
      return { formula, gadget, terrain, map: mapCells(gadget, terrain.quads), optimum: maxSatisfiable(formula), solution: null, failure: null, readback: null, certificate: null, checked: 0 };
    },
    built(b) {
      const { x0, y0, x1, y1 } = b.gadget.bounds;
      canvas.fit(Float64Array.of(x0, y0, 0, x1, y1, 0), 12);
    },
    job: (b) => ({ points: b.gadget.points, objective: 'max-convex-edges', method: 'auto', epsilon: 0.1, order: 1 }),
    solved(b) {
      if (!b.solution) return;
      b.readback = readBack(b.gadget, b.map, b.solution.choice);
      certifyInSlices(b);
    },
    render: () => render(),
  });

  /** Scores the pattern of every assignment, a few per task. */
  function certifyInSlices(b: Built): void {
    const n = b.formula.names.length;
    const evaluate = (choice: Uint8Array) => b.terrain.evaluate(choice)['max-convex-edges'];
    // The same check as certify() in gadgetCheck.ts, 32 assignments per task.
    const total = 1 << n;
    const values: number[] = [];
    const step = () => {
      if (!runner.current(b)) return;
      const end = Math.min(total, b.checked + 32);
      for (let mask = b.checked; mask < end; mask++) {
        const a = Array.from({ length: n }, (_, v) => ((mask >> v) & 1) === 1);
        values.push(evaluate(choiceFor(b.map, canonicalStates(b.gadget, a), b.solution!.choice)));
      }
      b.checked = end;
      if (end < total) {
        render();
        window.setTimeout(step, 0);
        return;
      }
      let constant: number | null = values[0]! - countSatisfied(b.formula, Array.from({ length: n }, () => false));
      values.forEach((v, mask) => {
        const a = Array.from({ length: n }, (_, x) => ((mask >> x) & 1) === 1);
        if (v - countSatisfied(b.formula, a) !== constant) constant = null;
      });
      b.certificate = { constant, tried: total, values };
      render();
    };
    window.setTimeout(step, 0);
  }

  function render(): void {
    canvas.redraw();
    const built = runner.built;
    caption.textContent = built?.solution
      ? 'Optimum: red convex, blue reflex diagonals · green clause edge convex · dashed: a skipped column'
      : 'The construction';
    if (!built) {
      showUnbuilt(summary, runner.error, vars, clauses, verdict);
      return;
    }
    const b = built;
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
            h('td', {}, h('i', { class: 'swatch', style: `background: ${CATEGORICAL[v % CATEGORICAL.length]}` }), f.names[v]!),
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
      const exact = b.solution!.optimal && b.solution!.value === cert.constant + b.optimum.best;
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

  function draw(c: CanvasRenderingContext2D, f: FittedCanvas): void {
    const b = runner.built;
    if (!b) return;
    const g = b.gadget;
    const p = g.points;
    const X = (i: number) => f.sx(p[3 * i]!);
    const Y = (i: number) => f.sy(p[3 * i + 1]!);
    // The coating: the lattice region, pale.
    c.fillStyle = '#eceeea';
    c.fillRect(f.sx(g.bounds.x0), f.sy(g.bounds.y1), (g.bounds.x1 - g.bounds.x0) * f.scale, (g.bounds.y1 - g.bounds.y0) * f.scale);
    c.fillStyle = 'rgba(90, 100, 96, 0.35)';
    const dot = Math.max(0.8, Math.min(1.6, f.scale * 0.08));
    for (let i = g.numLow; i < p.length / 3; i++) c.fillRect(X(i) - dot / 2, Y(i) - dot / 2, dot, dot);
    // Cells by variable, with their diagonal.
    const convex = b.solution ? cellStates(b.map, b.solution.choice) : g.cells.map((_, i) => b.map.delaunayIsConvex[i] === 1);
    const red = new Path2D(), blue = new Path2D(), outline = new Path2D(), skips = new Path2D();
    g.cells.forEach((cell, i) => {
      const [sw, se, ne, nw] = cell.corners;
      const path = new Path2D();
      path.moveTo(X(sw), Y(sw));
      path.lineTo(X(se), Y(se));
      path.lineTo(X(ne), Y(ne));
      path.lineTo(X(nw), Y(nw));
      path.closePath();
      c.fillStyle = tint(CATEGORICAL[cell.variable % CATEGORICAL.length]!, cell.clause < 0 ? 0.3 : 0.5);
      c.fill(path);
      outline.addPath(path);
      if (cell.w > 1) skips.addPath(path);
      const target = convex[i] ? red : blue;
      if (convex[i]) {
        target.moveTo(X(sw), Y(sw));
        target.lineTo(X(ne), Y(ne));
      } else {
        target.moveTo(X(se), Y(se));
        target.lineTo(X(nw), Y(nw));
      }
    });
    c.strokeStyle = 'rgba(255, 255, 255, 0.9)';
    c.lineWidth = 1;
    c.stroke(outline);
    const w = Math.max(1, Math.min(2.2, f.scale * 0.12));
    c.lineWidth = w;
    c.strokeStyle = EDGE_COLORS.convex;
    c.stroke(red);
    c.strokeStyle = EDGE_COLORS.reflex;
    c.stroke(blue);
    c.setLineDash([4, 3]);
    c.strokeStyle = '#111';
    c.lineWidth = 1.4;
    c.stroke(skips);
    c.setLineDash([]);
    // Clause meeting edges.
    c.font = `700 ${Math.max(10, Math.min(14, f.scale * 0.7))}px system-ui, sans-serif`;
    c.textAlign = 'center';
    c.textBaseline = 'middle';
    b.gadget.clauses.forEach((cl, k) => {
      const a = g.cells[cl.tentacles[0].cells.at(-1)!]!;
      const z = g.cells[cl.tentacles[1].cells.at(-1)!]!;
      const shared = a.corners.filter((v) => z.corners.includes(v));
      if (shared.length !== 2) return;
      const good = b.readback?.edgeConvex[k];
      c.strokeStyle = good === undefined ? '#333' : good ? '#17804a' : '#9aa19e';
      c.lineWidth = Math.max(3, f.scale * 0.28);
      c.lineCap = 'round';
      c.beginPath();
      c.moveTo(X(shared[0]!), Y(shared[0]!));
      c.lineTo(X(shared[1]!), Y(shared[1]!));
      c.stroke();
      const mx = (X(shared[0]!) + X(shared[1]!)) / 2;
      const my = (Y(shared[0]!) + Y(shared[1]!)) / 2 + (cl.page === 'top' ? -1 : 1) * f.scale * 1.4;
      label(c, `C${k + 1}`, mx, my, good === false ? '#6b716e' : '#17804a');
    });
    // Pool labels: variable = value.
    g.pools.forEach((pool) => {
      const v = pool.variable;
      const text = `${b.formula.names[v]}${b.readback ? ` = ${b.readback.assignment[v] ? 'T' : 'F'}` : ''}`;
      label(c, text, f.sx(pool.x0 + pool.w / 2), f.sy(pool.y0 + pool.h / 2), CATEGORICAL[v % CATEGORICAL.length]!);
    });
  }

  function label(c: CanvasRenderingContext2D, text: string, x: number, y: number, color: string): void {
    const m = c.measureText(text);
    const pad = 4;
    const hgt = parseFloat(c.font.split(' ')[1]!) + 4;
    c.fillStyle = 'rgba(255, 255, 255, 0.92)';
    c.beginPath();
    c.roundRect(x - m.width / 2 - pad, y - hgt / 2, m.width + 2 * pad, hgt, 4);
    c.fill();
    c.strokeStyle = color;
    c.lineWidth = 1.2;
    c.stroke();
    c.fillStyle = color;
    c.fillText(text, x, y + 0.5);
  }

  return {
    id: 'gadget',
    label: 'Hardness gadget',
    root,
    activate() {
      active = true;
      if (!runner.built && !runner.error) runner.run();
      canvas.redraw();
    },
    deactivate() {
      active = false;
    },
    changed() {
      // The gadget does not depend on the page's terrain.
      void active;
    },
    hooks() {
      const b = runner.built;
      return {
        error: runner.error,
        formula: input.value,
        variables: b?.formula.names ?? [],
        clauses: b ? b.formula.clauses.map((c) => c.map((l) => ({ variable: l.variable, negated: l.negated }))) : [],
        optimum: b?.optimum.best ?? null,
        points: b ? b.gadget.points.length / 3 : 0,
        solved: b?.solution != null,
        failure: b?.failure ?? null,
        value: b?.solution?.value ?? null,
        optimal: b?.solution?.optimal ?? null,
        method: b?.solution?.method ?? null,
        assignment: b?.readback?.assignment ?? null,
        edgeConvex: b?.readback?.edgeConvex ?? null,
        checked: b?.checked ?? 0,
        certificate: b?.certificate ? { constant: b.certificate.constant, tried: b.certificate.tried } : null,
      };
    },
  };
}
