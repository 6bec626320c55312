// What the three hardness-gadget views share in the DOM: a pane with a formula
// box, a "Build and solve" button, a status line and a verdict; the summary,
// solver line and clause table of a built gadget; and the tab that builds on
// first show. The logic behind them is in gadgetModel.ts.
import { h } from '../ui/dom.ts';
import type { FittedCanvas } from './canvas.ts';
import { clauseText } from './chainLayout.ts';
import { button, createPane } from './common.ts';
import { literalTrue, type Cnf, type Literal } from './formula.ts';
import type { BuiltGadget, GadgetRunner, Verdict } from './gadgetModel.ts';
import type { TeachView } from './view.ts';

export interface GadgetPane {
  root: HTMLElement;
  side: HTMLElement;
  main: HTMLElement;
  caption: HTMLElement;
  input: HTMLTextAreaElement;
  build: HTMLButtonElement;
  buttons: HTMLElement;
  summary: HTMLElement;
  verdict: HTMLElement;
}

/** The pane, its side opened by the formula's label, box and buttons (the view
 * appends the rest: status, verdict, tables, legend). */
export function createGadgetPane(o: {
  id: string;
  title: string;
  lead: (Node | string)[];
  label: string;
  formula: string;
  rows: number;
  ariaLabel: string;
  buildTitle: string;
  run: () => void;
}): GadgetPane {
  const { root, side, main, caption } = createPane(o.id, o.title, o.lead);
  const input = h('textarea', { id: `${o.id}-formula`, rows: o.rows, spellcheck: false, 'aria-label': o.ariaLabel });
  input.value = o.formula;
  const build = button(`${o.id}-build`, 'Build and solve', o.buildTitle, () => o.run(), false);
  const buttons = h('div', { class: 'buttons' }, build);
  const summary = h('p', { class: 'teach-status', id: `${o.id}-summary`, 'aria-live': 'polite' });
  const verdict = h('p', { class: 'teach-verdict', id: `${o.id}-verdict` });
  side.append(h('label', { for: `${o.id}-formula`, class: 'teach-label' }, o.label), input, buttons);
  return { root, side, main, caption, input, build, buttons, summary, verdict };
}

/** The status line when there is nothing built (the layout's message, or a
 * prompt), and the built gadget's other panels emptied. */
export function showUnbuilt(summary: HTMLElement, error: string | null, ...panels: HTMLElement[]): void {
  summary.replaceChildren(error ? h('span', { class: 'error' }, `Cannot build the gadget: ${error}.`) : 'Type a formula and press Build and solve.');
  for (const panel of panels) panel.replaceChildren();
}

/** The verdict's check, marked for the tests (`#<id>-check`, data-ok). */
export const checkSpan = (id: string, v: Verdict) => h('span', { id: `${id}-check`, 'data-ok': String(v.holds), class: v.holds ? 'good' : 'bad' }, v.text);

/** "3 variables, 2 clauses: satisfiable (all 2^3 assignments tried)". */
export function formulaLine(id: string, f: Cnf, satisfiable: boolean): (Node | string)[] {
  const n = f.names.length;
  return [
    `${n} variable${n === 1 ? '' : 's'}, ${f.clauses.length} clause${f.clauses.length === 1 ? '' : 's'}: `,
    h('b', { id: `${id}-satisfiable`, 'data-value': String(satisfiable) }, satisfiable ? 'satisfiable' : 'unsatisfiable'),
    ` (all 2`,
    h('sup', {}, String(n)),
    ` assignments tried). `,
  ];
}

/** What the exact solver found (`finds`: the value in words), its failure, or that it runs. */
export function solverLine(b: BuiltGadget, finds: (value: number) => string): Node | string {
  if (b.solution) return `The library (exact${b.solution.optimal ? ', proven optimal' : ', not proven optimal'}) finds ${finds(b.solution.value)} in ${b.solution.timeMs.toFixed(0)} ms.`;
  return b.failure ? h('span', { class: 'error' }, `The library could not solve it: ${b.failure}.`) : 'Solving…';
}

/** The clause table of a 3.1 or 3.2 gadget: each clause vertex, whether the values
 * read from the optimum satisfy its clause, and what its vertex is there. */
export function fillClauseTable(
  table: HTMLElement,
  f: Cnf,
  vertices: readonly { clause: number; point: number; literals: Literal[] }[],
  read: readonly boolean[] | null,
  vertex: ((point: number) => string) | null,
  titles: { satisfied: string; vertex: string },
): void {
  table.replaceChildren(
    h('thead', {}, h('tr', {}, h('th', {}, '#'), h('th', {}, 'clause'), h('th', { title: titles.satisfied }, 'satisfied'), h('th', { title: titles.vertex }, 'vertex'))),
    h(
      'tbody',
      {},
      ...vertices.map((cv) =>
        h(
          'tr',
          {},
          h('td', {}, `C${cv.clause + 1}`),
          h('td', {}, clauseText(f, cv.literals)),
          h('td', {}, read ? (cv.literals.some((l) => literalTrue(l, read)) ? '✓' : '✗') : ''),
          h('td', {}, vertex ? vertex(cv.point) : ''),
        ),
      ),
    ),
  );
}

/** A gadget's tab: built on first show, independent of the page's terrain. */
export function gadgetTab<B extends BuiltGadget>(
  o: { root: HTMLElement; runner: GadgetRunner<B>; canvas: FittedCanvas; hooks: () => Record<string, unknown> },
): TeachView {
  return {
    root: o.root,
    activate() {
      if (!o.runner.built && !o.runner.error) o.runner.run();
      o.canvas.redraw();
    },
    deactivate() {},
    changed() {
      // The gadget does not depend on the page's terrain.
    },
    hooks: o.hooks,
  };
}
