// What hodt costs a page: `node tests/pack/sizes.mjs` after `npm run build`.
// Raw, gzip (zlib level 9) and brotli sizes of the wasm, the Emscripten glue, the
// library JS as shipped, and of what a Vite production build of
// `import { loadHodt } from 'hodt'` emits (minified), and the npm tarball's size
// and file count. Prints them as Markdown; `--write` puts them in the docs
// between their markers (docs/api.md: the size section; README.md: the totals),
// `--check` exits 1 when the docs say something else (the package test runs it).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { brotliCompressSync, constants, gzipSync } from 'node:zlib';
import { updateBlocks } from '../../scripts/docBlocks.mjs';

const repo = fileURLToPath(new URL('../../', import.meta.url));
const dist = join(repo, 'dist');

const gzip = (b) => gzipSync(b, { level: 9 }).length;
const brotli = (b) => brotliCompressSync(b, { params: { [constants.BROTLI_PARAM_QUALITY]: 11 } }).length;
const kB = (n) => `${(n / 1024).toFixed(1)} KiB`;
// The tarball in tenths of a MiB: its bytes move with every edit of the shipped docs.
const MiB = (n) => `${(n / 1024 / 1024).toFixed(1)} MiB`;
const rows = [];
const row = (what, buffers) => {
  const all = Buffer.concat(buffers);
  // Files are compressed one by one, as a server sends them.
  const sum = (f) => buffers.reduce((s, b) => s + f(b), 0);
  rows.push([what, kB(all.length), kB(sum(gzip)), kB(sum(brotli))]);
};
const read = (f) => readFileSync(join(dist, f));

const library = readdirSync(dist).filter((f) => f.endsWith('.js') && !['cli.js', 'demoServer.js', 'three.js', 'export.js'].includes(f));
const exporters = ['export.js', ...readdirSync(join(dist, 'export')).filter((f) => f.endsWith('.js')).map((f) => `export/${f}`)];
row('`dist/wasm/hodt.wasm`', [read('wasm/hodt.wasm')]);
row('`dist/wasm/hodt.mjs` (Emscripten glue)', [read('wasm/hodt.mjs')]);
row(`library JS as shipped (${library.length} files, unminified)`, library.map(read));
row('`hodt/three` as shipped', [read('three.js')]);
row(`\`hodt/export\` as shipped (${exporters.length} files, unminified)`, exporters.map(read));

// A user's production bundle: Vite (Rolldown, minified) of one import.
const { build } = await import(join(repo, 'node_modules/vite/dist/node/index.js'));
const tmp = mkdtempSync(join(tmpdir(), 'hodt-sizes-'));
try {
  const entry = join(tmp, 'entry.js');
  writeFileSync(entry, `import { loadHodt } from ${JSON.stringify(join(dist, 'index.js'))};\nglobalThis.hodt = await loadHodt();\n`);
  const out = await build({
    root: tmp,
    configFile: false,
    logLevel: 'silent',
    build: { write: false, target: 'es2022', rollupOptions: { input: entry } },
  });
  const output = (Array.isArray(out) ? out[0] : out).output;
  const js = output.filter((o) => o.type === 'chunk').map((o) => Buffer.from(o.code));
  const wasm = output.filter((o) => o.fileName.endsWith('.wasm')).map((o) => Buffer.from(o.source));
  row('Vite build of `import { loadHodt } from "hodt"`: JS (minified)', js);
  row('same build: wasm', wasm);
  row('**total a page downloads**', [...js, ...wasm]);
} finally {
  rmSync(tmp, { recursive: true, force: true });
}

const [pack] = JSON.parse(execFileSync('npm', ['pack', '--dry-run', '--json'], { cwd: repo, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }));

const table = ['| what | raw | gzip -9 | brotli |', '|---|---:|---:|---:|', ...rows.map((r) => `| ${r.join(' | ')} |`)].join('\n');
const exportRow = rows.find((r) => r[0].startsWith('`hodt/export`'));
const files = exporters.length;
// What the docs say, each between its markers.
const generated = {
  'docs/api.md': {
    sizes: `${table}

\`hodt/export\` is not part of that bundle: a page that imports it adds ${exportRow[1]} of
JavaScript as shipped (${files} files; ${exportRow[2]} gzipped), no wasm.

npm tarball: ${pack.entryCount} files, ${MiB(pack.size)} packed, ${MiB(pack.unpackedSize)} unpacked.`,
  },
  'README.md': {
    sizes: `About ${Math.round(kBOf(rows.at(-1)[2]))} KiB gzipped in total (wasm ${Math.round(kBOf(rows[0][2]))} KiB)`,
  },
};
function kBOf(text) {
  return Number(/([\d.]+) KiB/.exec(text)[1]);
}

const mode = process.argv[2];
// Sizes written from a tree with uncommitted sources are not the sizes of any
// commit: a clean clone builds another wasm, and its package test fails.
if (mode === '--write') {
  let dirty = '';
  try {
    dirty = execFileSync('git', ['status', '--porcelain', '--', 'core', 'wasm', 'web/src', 'CMakeLists.txt'], { cwd: repo, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
  } catch {} // (not a git checkout: nothing to compare with)
  if (dirty) console.warn(`sizes.mjs: uncommitted sources; the sizes written are of this tree, not of a commit:\n${dirty}`);
}
if (mode === '--write' || mode === '--check') {
  const stale = updateBlocks(repo, 'tests/pack/sizes.mjs', generated, { write: mode === '--write' });
  if (mode === '--check' && stale.length) {
    console.error(`${stale.join(', ')}: sizes differ from what the build measures; run \`node tests/pack/sizes.mjs --write\``);
    process.exit(1);
  }
} else {
  console.log(`${generated['docs/api.md'].sizes}\n\n${generated['README.md'].sizes}`);
}
