import createHodtModule, { type HodtModule, type ModuleOptions } from './wasm/hodt.mjs';

export interface LoadOptions {
  /** Where hodt.wasm is served (browsers); default: next to this module. */
  wasmUrl?: string | URL;
  /** The bytes of hodt.wasm, if you have them already (any environment). */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

const isNode = typeof process !== 'undefined' && typeof process.versions?.node === 'string';

/** Loads and instantiates the wasm module. */
export async function loadModule(options: LoadOptions = {}): Promise<HodtModule> {
  const url = options.wasmUrl ?? new URL('./wasm/hodt.wasm', import.meta.url);
  const init: ModuleOptions = {};
  if (options.wasmBinary) {
    init.wasmBinary = options.wasmBinary;
  } else if (isNode && String(url).startsWith('file:')) {
    // Node's fetch cannot read file: URLs; read the file instead. The specifier is
    // a variable so that bundlers for the browser leave node:fs alone.
    const fsName = 'node:fs/promises';
    const fs = (await import(/* @vite-ignore */ fsName)) as typeof import('node:fs/promises');
    init.wasmBinary = await fs.readFile(new URL(String(url)));
  } else {
    init.locateFile = () => String(url);
  }
  return createHodtModule(init);
}
