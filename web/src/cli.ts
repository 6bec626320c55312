#!/usr/bin/env node
// `hodt` on the command line: the core's CLI (core/src/cli/cli.cpp) run in wasm, with
// Node's file system to read FILE or standard input (GeoTIFF and LAS/LAZ through
// hodt/loaders) and to write --output files (the mesh formats with hodt/export's
// writers), and stderr for progress. `hodt demo` serves the teaching demo.
import { closeSync, openSync, readFileSync, writeFileSync, writeSync } from 'node:fs';
import type { MeshData, MeshFormat } from './export.js';

const args = process.argv.slice(2);

// hodt.wasm compiles in V8's background threads while Node loads the library's
// modules (imported below, not at the top, so that they load after this starts).
// A file that cannot be read or compiled is left to loadHodt, which says why.
function compileWasm(): Promise<WebAssembly.Module | undefined> {
  try {
    return WebAssembly.compile(readFileSync(new URL('./wasm/hodt.wasm', import.meta.url))).catch(() => undefined);
  } catch {
    return Promise.resolve(undefined);
  }
}
const compiling = args[0] === 'demo' ? undefined : compileWasm();

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

// The mesh writers load only for a run that names an --output file (the core asks
// for one synchronously, so they load before it runs).
const exporters = args.includes('--output') ? await import('./export.js') : undefined;

// Part by part: a large TIN as GeoJSON is longer than any JavaScript string.
function writeMesh(path: string, format: MeshFormat, mesh: MeshData): void {
  if (!exporters) throw new Error('the mesh writers were not loaded: no --output was given');
  const parts = exporters.exportMeshParts(format, mesh); // checks the mesh before the file is made
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

// `hodt demo`: the teaching demo shipped in the package, served by Node alone.
if (args[0] === 'demo') {
  const { DEMO_HELP, demoOptions, serveDemo } = await import('./demoServer.js');
  const options = demoOptions(args.slice(1));
  if (typeof options === 'string') {
    process.stderr.write(`${options}\n`);
    process.exit(2);
  }
  if (options.help) {
    process.stdout.write(DEMO_HELP);
    process.exit(0);
  }
  try {
    await serveDemo(options);
    process.exit(0);
  } catch (e) {
    const error = failure(e) as NodeJS.ErrnoException;
    process.stderr.write(`hodt demo: cannot serve on port ${options.port}: ${error.code ?? error.message}\n`);
    process.exit(1);
  }
}
const { loadHodt } = await import('./index.js');
const wasmModule = await compiling;
const hodt = await loadHodt(wasmModule ? { wasmModule } : {}).catch((e: unknown) => {
  // (an install without its wasm: one line, not a stack)
  process.stderr.write(`hodt: ${failure(e).message}\n`);
  process.exit(1);
});
const read = (path: string): Uint8Array | Error => {
  try {
    return readFileSync(path === '-' ? 0 : path); // bytes: the core decodes text itself
  } catch (e) {
    return failure(e);
  }
};

// A dry run names the file the core will read (its reader answers nothing), so
// that a GeoTIFF or LAS/LAZ file is decoded first, by the opt-in loaders, into
// the x y z text the core reads (numbers printed exactly).
let path: string | undefined;
const unused = () => new Error('EPERM'); // (the dry run stops at reading, before any write)
hodt.runCli(
  args,
  (p) => {
    path = p;
    return new Error('ENOENT');
  },
  { writeFile: unused, writeMesh: unused, progress: () => {}, stderrIsTerminal: false },
);
let input: Uint8Array | Error | undefined;
const notes: string[] = [];
// A GIS file's points reach the core as lines of text, one per point: the core's
// "(line N)" is then that point's cell or record, named as the loader read it.
let origin: ((i: number) => string) | undefined;
if (path !== undefined) {
  input = read(path);
  if (!(input instanceof Error)) {
    const { sniffFormat } = await import('./loaders/sniff.js');
    const format = sniffFormat(input);
    if (format) {
      const { readGeoTIFF, readLAS, RASTER_MAX_EDGE_CELLS } = await import('./loaders/index.js');
      const at = args.indexOf('--classes');
      const classes = at >= 0 ? (args[at + 1] as 'ground' | 'all') : 'ground';
      try {
        const cloud = format === 'geotiff' ? await readGeoTIFF(input) : await readLAS(input, { classes });
        const lines: string[] = [];
        for (let i = 0; i < cloud.xyz.length; i += 3) lines.push(`${cloud.xyz[i]} ${cloud.xyz[i + 1]} ${cloud.xyz[i + 2]}`);
        input = Buffer.from(lines.join('\n') + '\n', 'utf8');
        origin = cloud.origin;
        for (const w of cloud.warnings) notes.push(`hodt: warning: ${path}: ${w}\n`);
        // The CRS the file names, written where the output format has a place.
        if (cloud.crs && !args.includes('--crs')) {
          args.push('--crs', cloud.crs);
          notes.push(`hodt: ${path}: coordinates in ${cloud.crs}, kept as read\n`);
        }
        // Point clouds repeat (x, y) across returns: keep the first unless told.
        if (format === 'las' && !args.includes('--dedupe')) args.push('--dedupe', 'first');
        // A raster with gaps gets its default domain, as the core gives ASCII grids.
        if (cloud.maxEdge !== undefined && !args.includes('--max-edge')) {
          args.push('--max-edge', String(cloud.maxEdge));
          notes.push(
            `hodt: note: ${path}: triangles with an edge longer than ${cloud.maxEdge} (${RASTER_MAX_EDGE_CELLS} cells) are outside the domain ` +
              'and not measured (--max-edge L to change, --max-edge none to measure every triangle)\n',
          );
        }
      } catch (e) {
        input = new Error(failure(e).message); // (a message, no code: the core prints it after the file's name)
      }
    }
  }
}
const result = hodt.runCli(
  args,
  (p) => (p === path && input !== undefined ? input : read(p)),
  {
    writeFile: (path, bytes) => attempt(() => writeFileSync(path, bytes)),
    writeMesh: (path, format, mesh) => attempt(() => writeMesh(path, format, mesh)),
    progress: (text) => {
      writeSync(2, text);
    },
    // Once the core accepts the input: the loaders' notes, then its own (a
    // refused input shows none).
    notes: (text) => {
      if (!args.includes('--quiet')) for (const n of notes.splice(0)) writeSync(2, n);
      writeSync(2, text);
    },
    stderrIsTerminal: process.stderr.isTTY === true,
  },
);
process.stdout.write(result.stdout);
process.stderr.write(origin ? result.stderr.replace(/\(line (\d+)\)/g, (_, line: string) => `(${origin!(Number(line) - 1)})`) : result.stderr);
process.exitCode = result.exitCode;
