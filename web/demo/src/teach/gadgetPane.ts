// What the three hardness-gadget views share in the DOM: the pane (the lead, a
// formula box, a "Build and solve" button, a status line and a verdict, then the
// view's own panels, its legend and a note on what the page does not show), the
// canvas, the runner that builds into them, and the tab that builds on first
// show. The logic behind them is in gadgetModel.ts.
import type { Hodt } from 'hodt';
import type { SolveJob } from '../solver/solverClient.ts';
import { h } from '../ui/dom.ts';
import { createFittedCanvas, type FittedCanvas } from './canvas.ts';
import { button, createPane, legend, paperLink, type LegendItem } from './common.ts';
import { gadgetRunner, type BuiltGadget, type GadgetRunner } from './gadgetModel.ts';
import type { TeachContext, TeachView } from './view.ts';

/** The panels every gadget view fills from its build. */
export interface GadgetPanels {
  /** The formula, the gadget and what the solver found (or why nothing is built). */
  summary: HTMLElement;
  /** Whether the reduction held on this instance. */
  verdict: HTMLElement;
}

/** A gadget view: what its pane says, how it builds and solves a formula, and
 * how it shows a build. */
export interface GadgetViewSpec<B extends BuiltGadget> {
  id: string;
  title: string;
  /** The lead's sentences, before "See Section <section> of the paper." */
  lead: readonly string[];
  section: string;
  formula: { label: string; text: string; rows: number; ariaLabel: string };
  buildTitle: string;
  /** Buttons after "Build and solve". */
  buttons?: readonly HTMLElement[];
  /** The side below the formula box, in order; the legend and the note follow. */
  panels(p: GadgetPanels): HTMLElement[];
  legend: readonly LegendItem[];
  /** What the page does not show: bold headings, each with its text, in one paragraph. */
  note: readonly (readonly [string, string])[];
  /** The canvas draws the current build, fitted to each new one (`fit`: the
   * points to frame, `margin` pixels around them). */
  canvas: { draw(c: CanvasRenderingContext2D, fc: FittedCanvas, b: B): void; label: string; fit(b: B): Float64Array; margin: number };
  /** Makes the build from the formula box, throwing one of `refusals` for a
   * formula it cannot take (its message is shown). */
  make(hodt: Hodt, text: string): B;
  refusals: readonly (new (...args: never[]) => Error)[];
  job(b: B): SolveJob;
  /** Runs once the solution (or failure) is in. */
  solved?(b: B): void;
  /** The canvas's caption once the optimum is in ("The construction" before). */
  solvedCaption: string;
  /** The panels besides the verdict that show a build: emptied when there is none. */
  unbuilt: readonly HTMLElement[];
  show(b: B, p: GadgetPanels): void;
  hooks(runner: GadgetRunner<B>, formula: string): Record<string, unknown>;
}

/** The view of a gadget spec; its runner and `render` (the canvas and the pane
 * shown again) for a view that adds to its build after the solve. */
export function createGadgetView<B extends BuiltGadget>(ctx: TeachContext, o: GadgetViewSpec<B>): { view: TeachView; runner: GadgetRunner<B>; render(): void } {
  const { root, side, main, caption } = createPane(o.id, o.title, [...o.lead, 'See ', paperLink(o.section), '.']);
  const input = h('textarea', { id: `${o.id}-formula`, rows: o.formula.rows, spellcheck: false, 'aria-label': o.formula.ariaLabel });
  input.value = o.formula.text;
  const build = button(`${o.id}-build`, 'Build and solve', o.buildTitle, () => runner.run(), false);
  const panels: GadgetPanels = {
    summary: h('p', { class: 'teach-status', id: `${o.id}-summary`, 'aria-live': 'polite' }),
    verdict: h('p', { class: 'teach-verdict', id: `${o.id}-verdict` }),
  };
  side.append(
    h('label', { for: `${o.id}-formula`, class: 'teach-label' }, o.formula.label),
    input,
    h('div', { class: 'buttons' }, build, ...(o.buttons ?? [])),
    ...o.panels(panels),
    legend(o.legend),
    h('p', { class: 'teach-note' }, ...o.note.flatMap(([heading, text]) => [h('b', {}, heading), text])),
  );
  const canvas = createFittedCanvas(main, (c, fc) => runner.built && o.canvas.draw(c, fc, runner.built), o.canvas.label);
  const render = (): void => {
    canvas.redraw();
    const b = runner.built;
    caption.textContent = b?.solution ? o.solvedCaption : 'The construction';
    if (b) return o.show(b, panels);
    panels.summary.replaceChildren(runner.error ? h('span', { class: 'error' }, `Cannot build the gadget: ${runner.error}.`) : 'Type a formula and press Build and solve.');
    for (const panel of [panels.verdict, ...o.unbuilt]) panel.replaceChildren();
  };
  const runner = gadgetRunner<B>(ctx, {
    text: () => input.value,
    refusals: o.refusals,
    make: (text) => o.make(ctx.hodt, text),
    built: (b) => canvas.fit(o.canvas.fit(b), o.canvas.margin),
    job: (b) => o.job(b),
    solved: (b) => o.solved?.(b),
    render,
  });
  // A gadget does not depend on the page's terrain: it is built on first show.
  const view: TeachView = {
    root,
    activate() {
      if (!runner.built && !runner.error) runner.run();
      canvas.redraw();
    },
    deactivate() {},
    changed() {},
    hooks: () => o.hooks(runner, input.value),
  };
  return { view, runner, render };
}
