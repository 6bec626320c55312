// What the three hardness-gadget views share: a pane with a formula box, a
// "Build and solve" button, a status line and a verdict; and the run of one
// build: parse and lay out the formula (a message when it cannot be), make the
// terrain, solve it in the teaching worker, and drop a result that a newer build
// superseded.
import type { Solution, Terrain } from 'hodt';
import { h } from '../ui/dom.ts';
import type { SolveJob } from '../solver/solverClient.ts';
import type { FittedCanvas } from './canvas.ts';
import { button, createPane, type TeachContext, type TeachView } from './common.ts';
import { FormulaError, literalTrue, parseCnf, type Cnf, type Literal } from './formula.ts';
import { clauseText } from './chainLayout.ts';

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

/** A formula for a gadget that takes clauses of 1 to maxLiterals literals over at
 * most maxVariables variables. */
export function parseGadgetFormula(text: string, maxLiterals: number, example: string, maxVariables: number): Cnf {
  const formula = parseCnf(text, 1, maxLiterals, example);
  if (formula.names.length > maxVariables) throw new FormulaError(`${formula.names.length} variables: this gadget takes at most ${maxVariables}`);
  return formula;
}

/** Whether the reduction held on a built instance, in words. */
export interface Verdict {
  holds: boolean | null;
  text: string;
}

/**
 * The verdict on a solved instance: unverified unless the optimum is proven;
 * else `explain` says what the assignments showed (`per`, ending in "and "),
 * whether the optimum is what the proof predicts, and how it compares (`found`
 * when it holds, `missed` when not).
 */
export function judgeReduction(s: Solution | null, explain: (s: Solution) => { per: string; holds: boolean; found: string; missed: string }): Verdict {
  if (!s) return { holds: null, text: '' };
  if (!s.optimal) return { holds: false, text: `The solver’s ${s.value} is not proven optimal, so this instance is not verified.` };
  const e = explain(s);
  return e.holds
    ? { holds: true, text: `Check: ${e.per}the proven optimum is ${s.value} ${e.found}: on this instance the reduction holds.` }
    : { holds: false, text: `Check failed: ${e.per}the proven optimum is ${s.value}${e.missed}: on this instance the reduction does not hold.` };
}

/** The verdict's check, marked for the tests (`#<id>-check`, data-ok). */
export const checkSpan = (id: string, v: Verdict) => h('span', { id: `${id}-check`, 'data-ok': String(v.holds), class: v.holds ? 'good' : 'bad' }, v.text);

/** What a 3.1 or 3.2 gadget's view built: its formula, the gadget (G), where its
 * pieces are among the terrain's quads (M), and what every assignment scores (C). */
export interface BuiltFormulaGadget<G extends { points: Float64Array } = { points: Float64Array }, M = unknown, C extends { wrong: readonly unknown[] } = { wrong: readonly unknown[] }> extends BuiltGadget {
  formula: Cnf;
  gadget: G;
  map: M;
  satisfying: boolean[] | null;
  certificate: C;
}

/** The hooks (tests/e2e) every formula gadget shares, and its own (`extra`). */
export function gadgetHooks<B extends BuiltFormulaGadget>(
  runner: GadgetRunner<B>,
  input: HTMLTextAreaElement,
  judge: (b: B) => Verdict,
  extra: (b: B | null) => Record<string, unknown>,
): () => Record<string, unknown> {
  return () => {
    const b = runner.built;
    return {
      error: runner.error,
      formula: input.value,
      points: b ? Array.from(b.gadget.points) : [],
      satisfiable: b ? b.satisfying !== null : null,
      solved: b?.solution != null,
      failure: b?.failure ?? null,
      value: b?.solution?.value ?? null,
      optimal: b?.solution?.optimal ?? null,
      wrongAssignments: b ? b.certificate.wrong.length : null,
      holds: b ? judge(b).holds : null,
      ...extra(b),
    };
  };
}

/** What every built gadget carries: its terrain and the solver's outcome. */
export interface BuiltGadget {
  terrain: Terrain;
  solution: Solution | null;
  failure: string | null;
}

export interface GadgetRunner<B extends BuiltGadget> {
  run(): void;
  readonly built: B | null;
  readonly error: string | null;
  /** Is this build still the current one? */
  current(b: B): boolean;
}

/**
 * One build at a time: `make` parses and lays out the formula (throwing one of
 * `refusals` for a formula it cannot take: its message is shown), `job` is the
 * solve, `solved` runs once the solution (or failure) is in, `render` after each
 * change.
 */
export function gadgetRunner<B extends BuiltGadget>(
  ctx: TeachContext,
  o: {
    text: () => string;
    refusals: readonly (new (...args: never[]) => Error)[];
    make: (text: string) => B;
    job: (b: B) => SolveJob;
    built?: (b: B) => void;
    solved?: (b: B) => void;
    render: () => void;
  },
): GadgetRunner<B> {
  let built: B | null = null;
  let error: string | null = null;
  let token = 0;
  const self: GadgetRunner<B> = {
    run() {
      const my = ++token;
      built?.terrain.dispose();
      built = null;
      error = null;
      let b: B;
      try {
        b = o.make(o.text());
      } catch (e) {
        if (!o.refusals.some((k) => e instanceof k)) throw e;
        error = (e as Error).message;
        o.render();
        return;
      }
      built = b;
      o.built?.(b);
      o.render();
      void ctx.solver.solve(o.job(b)).then((out) => {
        if (my !== token) return;
        if (out.status !== 'solved') b.failure = out.status === 'failed' ? out.message : 'cancelled';
        else b.solution = out.solution;
        o.solved?.(b);
        o.render();
      });
    },
    get built() {
      return built;
    },
    get error() {
      return error;
    },
    current: (b) => b === built,
  };
  return self;
}

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

/** "Values read from the fans: x = F, y = T" and what follows it. */
export const valuesText = (f: Cnf, where: string, a: readonly boolean[]) => `Values read from the ${where}: ${f.names.map((name, v) => `${name} = ${a[v] ? 'T' : 'F'}`).join(', ')}`;

/** A gadget's tab: built on first show, independent of the page's terrain. */
export function gadgetTab<B extends BuiltGadget>(
  o: { id: string; label: string; root: HTMLElement; runner: GadgetRunner<B>; canvas: FittedCanvas; hooks: () => Record<string, unknown> },
): TeachView {
  return {
    id: o.id,
    label: o.label,
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
