import { HodtError } from './errors.js';
import createHodtModule, { type HodtModule, type ModuleOptions } from './wasm/hodt.mjs';

/**
 * Where the wasm comes from. By default hodt.wasm is found next to this module
 * (dist/wasm/hodt.wasm): read from disk in Node, fetched in browsers and workers;
 * bundlers that understand `new URL('...', import.meta.url)` (Vite, webpack 5,
 * Rollup, esbuild with a plugin, Parcel) copy it for you. Give at most one option.
 */
export interface LoadOptions {
  /** Where hodt.wasm is served, if not next to the JS (a CDN, a custom asset path). */
  wasmUrl?: string | URL;
  /** The bytes of hodt.wasm, if you have them already. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** hodt.wasm already compiled (for example by a platform that imports .wasm
   * files as modules). */
  wasmModule?: WebAssembly.Module;
}

export const isNode = typeof process === 'object' && typeof process.versions?.node === 'string';

async function readFileUrl(url: URL): Promise<Uint8Array> {
  // Node's fetch cannot read file: URLs. The module name is a variable so that
  // bundlers for the browser leave node:fs alone.
  const name = 'node:fs/promises';
  const fs = (await import(/* @vite-ignore */ /* webpackIgnore: true */ name)) as typeof import('node:fs/promises');
  return fs.readFile(url);
}

/** Loads and instantiates the wasm module. */
export async function loadModule(options: LoadOptions = {}): Promise<HodtModule> {
  const url = options.wasmUrl ?? new URL('./wasm/hodt.wasm', import.meta.url);
  const init: ModuleOptions = {};
  const where = options.wasmModule ? 'the given WebAssembly.Module' : options.wasmBinary ? 'the given bytes' : String(url);
  // instantiateWasm cannot report a failure to the glue: it rejects `failure`.
  let fail: (reason: unknown) => void = () => {};
  const failure = new Promise<never>((_, reject) => (fail = reject));
  try {
    if (options.wasmModule) {
      const module = options.wasmModule;
      init.instantiateWasm = (imports, receive) => {
        WebAssembly.instantiate(module, imports as WebAssembly.Imports).then((instance) => receive(instance, module), fail);
        return {};
      };
    } else if (options.wasmBinary) {
      init.wasmBinary = options.wasmBinary;
    } else if (isNode && String(url).startsWith('file:')) {
      init.wasmBinary = await readFileUrl(new URL(String(url)));
    } else {
      init.locateFile = () => String(url);
    }
    return await Promise.race([createHodtModule(init), failure]);
  } catch (e) {
    throw new HodtError(`could not load hodt.wasm from ${where}: ${e instanceof Error ? e.message : String(e)}`, { cause: e });
  }
}
