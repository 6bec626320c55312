// What the three hardness-gadget views share, without the DOM: the run of one
// build (parse and lay out the formula, or say why not; make the terrain, solve
// it in the teaching worker, and drop a result that a newer build superseded).
import type { Solution, Terrain } from 'hodt';
import type { SolveJob } from '../solver/solverClient.ts';
import type { TeachContext } from './view.ts';

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
