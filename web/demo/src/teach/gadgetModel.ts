// What the three hardness-gadget views share, without the DOM: the formula they
// take, the run of one build (parse and lay out the formula, or say why not;
// make the terrain, solve it in the teaching worker, and drop a result that a
// newer build superseded), the verdict on a solved instance, and the hooks.
import type { Solution, Terrain } from 'hodt';
import type { SolveJob } from '../solver/solverClient.ts';
import { FormulaError, parseCnf, type Cnf } from './formula.ts';
import type { TeachContext } from './view.ts';

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
  formula: () => string,
  judge: (b: B) => Verdict,
  extra: (b: B | null) => Record<string, unknown>,
): () => Record<string, unknown> {
  return () => {
    const b = runner.built;
    return {
      error: runner.error,
      formula: formula(),
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

/** "Values read from the fans: x = F, y = T" and what follows it. */
export const valuesText = (f: Cnf, where: string, a: readonly boolean[]) => `Values read from the ${where}: ${f.names.map((name, v) => `${name} = ${a[v] ? 'T' : 'F'}`).join(', ')}`;

