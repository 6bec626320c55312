#!/usr/bin/env node
// `hodt` on the command line: the core's CLI (core/src/cli.cpp) run in wasm, with
// Node's file system to read FILE or standard input.
import { readFileSync } from 'node:fs';
import { loadHodt } from './index.js';

const hodt = await loadHodt();
const result = hodt.runCli(process.argv.slice(2), (path) => {
  try {
    return readFileSync(path === '-' ? 0 : path, 'utf8');
  } catch (e) {
    const code = (e as NodeJS.ErrnoException).code;
    return new Error(code === 'ENOENT' ? 'no such file' : code === 'EISDIR' ? 'is a directory' : String((e as Error).message));
  }
});
process.stdout.write(result.stdout);
process.stderr.write(result.stderr);
process.exitCode = result.exitCode;
