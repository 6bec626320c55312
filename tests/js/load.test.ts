// The ways of loading the wasm module (LoadOptions), in Node.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { HodtError } from '../../web/src/errors.js';
import { loadModule } from '../../web/src/load.js';

const wasmUrl = new URL('../../web/src/wasm/hodt.wasm', import.meta.url);

async function works(options: Parameters<typeof loadModule>[0]) {
  const m = await loadModule(options);
  expect(m.objectiveTable().length).toBe(13);
}

describe('loadModule', () => {
  it('finds hodt.wasm next to the module by default', () => works({}));
  it('takes a file: URL', () => works({ wasmUrl }));
  it('takes the bytes', () => works({ wasmBinary: readFileSync(wasmUrl) }));
  it('takes a compiled WebAssembly.Module', async () => works({ wasmModule: await WebAssembly.compile(readFileSync(wasmUrl)) }));
  it('a missing file is a HodtError naming the URL', async () => {
    await expect(loadModule({ wasmUrl: new URL('file:///nowhere/hodt.wasm') })).rejects.toThrow(HodtError);
    await expect(loadModule({ wasmUrl: new URL('file:///nowhere/hodt.wasm') })).rejects.toThrow(/could not load hodt\.wasm from file:\/\/\/nowhere\/hodt\.wasm/);
  });
  it('bytes that are not wasm are a HodtError', async () => {
    await expect(loadModule({ wasmBinary: new Uint8Array([1, 2, 3, 4]) })).rejects.toThrow(HodtError);
  });
});
