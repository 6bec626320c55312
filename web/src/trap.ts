// A wasm trap (WebAssembly.RuntimeError: out of bounds, unreachable) leaves the
// module's memory in an unknown state: no later answer from it can be trusted.
// After the first trap, every call into that module throws InternalError saying
// so, instead of failing at random; loadHodt() then loads a new module.
import { InternalError } from './errors.js';
import type { HodtModule } from './wasm/hodt.mjs';

type Callable = (...args: unknown[]) => unknown;

// The module's own functions (bindings.cpp), wrapped with the terrain class's methods.
const FUNCTIONS = ['fromPoints', 'fromTriangulation', 'readPoints', 'runCli', 'objectiveTable', 'heapSize'];

/** Wraps the module's functions and its terrain class's methods in place. */
export function stopAfterTrap(module: HodtModule, onTrap: () => void): void {
  let trap: Error | null = null;
  const wrap = (owner: Record<string, unknown>, name: string) => {
    const f = owner[name] as Callable;
    owner[name] = function (this: unknown, ...args: unknown[]) {
      if (trap && name === 'delete') return undefined; // (nothing to free in a module that is gone)
      if (trap) throw new InternalError(`hodt's wasm module stopped after a trap (${trap.message}); load a new one with loadHodt()`);
      try {
        return f.apply(this, args);
      } catch (e) {
        if (!(e instanceof WebAssembly.RuntimeError)) throw e;
        trap = e;
        onTrap();
        throw new InternalError(`hodt's wasm module trapped (${e.message}); please report it with the input. Later calls on it fail; loadHodt() loads a new one`, { cause: e });
      }
    };
  };
  const functions = module as unknown as Record<string, unknown>;
  for (const name of FUNCTIONS) if (typeof functions[name] === 'function') wrap(functions, name);
  const terrains = (functions.TerrainHandle as { prototype: Record<string, unknown> }).prototype;
  for (const name of [...Object.getOwnPropertyNames(terrains), 'delete'])
    if (name !== 'constructor' && typeof terrains[name] === 'function') wrap(terrains, name);
}
