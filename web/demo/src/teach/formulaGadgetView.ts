// The view of a 3.1 or 3.2 reduction (Mixed vertices, Max degree): a gadget view
// (gadgetPane.ts) that builds, solves and judges by the reduction's kind
// (formulaGadget.ts) and shows a build as the formula, the gadget in a sentence,
// what the exact solver found, the clause table (the values read from the
// optimum and what each clause vertex is there) and the verdict.
import { h } from '../ui/dom.ts';
import { clauseText } from './chainLayout.ts';
import { FormulaError, literalTrue, type Cnf } from './formula.ts';
import {
  formulaGadgetHooks,
  formulaGadgetJob,
  makeFormulaGadget,
  type AssignmentCheck,
  type BuiltFormulaGadget,
  type ClauseVertex,
  type FormulaGadget,
  type FormulaGadgetKind,
  type ReadValues,
} from './formulaGadget.ts';
import type { BuiltGadget } from './gadgetModel.ts';
import { createGadgetView, type GadgetPanels, type GadgetViewSpec } from './gadgetPane.ts';
import { teachView, type TeachViewSpec } from './view.ts';

export interface FormulaGadgetViewSpec<Id extends string, B extends BuiltFormulaGadget>
  extends Pick<GadgetViewSpec<B>, 'title' | 'lead' | 'section' | 'formula' | 'buildTitle' | 'legend' | 'note' | 'solvedCaption'> {
  id: Id;
  label: string;
  /** The canvas, fitted to the gadget's points. */
  canvas: Omit<GadgetViewSpec<B>['canvas'], 'fit'>;
  /** The gadget in a sentence, after the formula's line. */
  gadget(b: B): string;
  /** The solver's value in words. */
  finds(value: number): string;
  /** Where the values are read from ("rows", "fans"). */
  where: string;
  /** What follows the values read in the verdict ('. ' if not given). */
  after?(b: B, read: ReadValues): string;
  /** What a clause vertex is in the optimum (`of`), and its column's title. */
  vertex: { title: string; of(b: B, choice: Uint8Array): (point: number) => string };
}

export function formulaGadgetView<const Id extends string, G extends FormulaGadget, M, C extends AssignmentCheck>(
  kind: FormulaGadgetKind<G, M, C>,
  spec: FormulaGadgetViewSpec<Id, BuiltFormulaGadget<G, M, C>>,
): TeachViewSpec<Id> {
  return teachView({
    id: spec.id,
    label: spec.label,
    create(ctx) {
      const clauses = h('table', { class: 'teach-table', id: `${spec.id}-clauses` });
      return createGadgetView<BuiltFormulaGadget<G, M, C>>(ctx, {
        ...spec,
        panels: ({ summary, verdict }) => [verdict, summary, clauses],
        canvas: { ...spec.canvas, fit: (b) => b.gadget.points },
        make: (hodt, text) => makeFormulaGadget(hodt, text, kind),
        refusals: [FormulaError, kind.layoutError],
        job: (b) => formulaGadgetJob(b, kind.objective),
        unbuilt: [clauses],
        show: (b, panels) => showBuilt(kind, spec, clauses, b, panels),
        hooks: (runner, formula) => formulaGadgetHooks(runner, formula, kind),
      }).view;
    },
  });
}

/** A build in the pane: the summary, the clause table, and the verdict (the
 * values read from the optimum and the check, marked for the tests as
 * `#<id>-check` with data-ok). */
function showBuilt<G extends FormulaGadget, M, C extends AssignmentCheck, B extends BuiltFormulaGadget<G, M, C>>(
  kind: FormulaGadgetKind<G, M, C>,
  spec: FormulaGadgetViewSpec<string, B>,
  clauses: HTMLElement,
  b: B,
  { summary, verdict }: GadgetPanels,
): void {
  const f = b.formula;
  summary.replaceChildren(...formulaLine(spec.id, f, b.satisfying !== null), spec.gadget(b), solverLine(b, spec.finds));
  const choice = b.solution?.choice ?? null;
  const read = choice ? kind.read(b.gadget, b.map, choice) : null;
  fillClauseTable(clauses, f, b.gadget.clauses, read?.assignment ?? null, choice ? spec.vertex.of(b, choice) : null, {
    satisfied: `by the values read from the ${spec.where} of the optimum`,
    vertex: spec.vertex.title,
  });
  const j = kind.judge(b);
  verdict.replaceChildren();
  if (j.holds === null) return;
  if (read) verdict.append(valuesText(f, spec.where, read.assignment), spec.after?.(b, read) ?? '. ');
  verdict.append(h('span', { id: `${spec.id}-check`, 'data-ok': String(j.holds), class: j.holds ? 'good' : 'bad' }, j.text));
}

/** "Values read from the fans: x = F, y = T" and what follows it. */
export const valuesText = (f: Cnf, where: string, a: readonly boolean[]) => `Values read from the ${where}: ${f.names.map((name, v) => `${name} = ${a[v] ? 'T' : 'F'}`).join(', ')}`;

/** "3 variables, 2 clauses: satisfiable (all 2^3 assignments tried)". */
function formulaLine(id: string, f: Cnf, satisfiable: boolean): (Node | string)[] {
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
function solverLine(b: BuiltGadget, finds: (value: number) => string): Node | string {
  if (b.solution) return `The library (exact${b.solution.optimal ? ', proven optimal' : ', not proven optimal'}) finds ${finds(b.solution.value)} in ${b.solution.timeMs.toFixed(0)} ms.`;
  return b.failure ? h('span', { class: 'error' }, `The library could not solve it: ${b.failure}.`) : 'Solving…';
}

/** The clause table: each clause vertex, whether the values read from the
 * optimum satisfy its clause, and what its vertex is there. */
function fillClauseTable(
  table: HTMLElement,
  f: Cnf,
  vertices: readonly ClauseVertex[],
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
