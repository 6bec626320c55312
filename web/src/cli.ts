#!/usr/bin/env node
// `hodt` on the command line: the core's CLI (core/src/cli.cpp) run in wasm, with
// Node's file system to read FILE or standard input and to write --output files
// (the mesh formats with hodt/export's writers), and stderr for progress.
import { closeSync, openSync, readFileSync, writeFileSync, writeSync } from 'node:fs';
import { exportMeshParts, type MeshData, type MeshFormat } from './export.js';
import { loadHodt } from './index.js';

// The core puts an Error's Node code (ENOENT, ...) in the same words as the native CLI.
const failure = (e: unknown): Error => (e instanceof Error ? e : new Error(String(e)));
const attempt = (write: () => void): Error | undefined => {
  try {
    write();
    return undefined;
  } catch (e) {
    return failure(e);
  }
};

// Part by part: a large TIN as GeoJSON is longer than any JavaScript string.
function writeMesh(path: string, format: MeshFormat, mesh: MeshData): void {
  const parts = exportMeshParts(format, mesh); // checks the mesh before the file is made
  const fd = openSync(path, 'w');
  try {
    for (const part of parts) {
      const bytes = typeof part === 'string' ? Buffer.from(part, 'utf8') : part;
      for (let at = 0; at < bytes.length; ) at += writeSync(fd, bytes, at);
    }
  } finally {
    closeSync(fd);
  }
}

const hodt = await loadHodt();
const result = hodt.runCli(
  process.argv.slice(2),
  (path) => {
    try {
      return readFileSync(path === '-' ? 0 : path); // bytes: the core decodes them
    } catch (e) {
      return failure(e);
    }
  },
  {
    writeFile: (path, text) => attempt(() => writeFileSync(path, text)),
    writeMesh: (path, format, mesh) => attempt(() => writeMesh(path, format, mesh)),
    progress: (text) => {
      writeSync(2, text);
    },
    stderrIsTerminal: process.stderr.isTTY === true,
  },
);
process.stdout.write(result.stdout);
process.stderr.write(result.stderr);
process.exitCode = result.exitCode;
