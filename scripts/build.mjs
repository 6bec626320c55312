// Builds everything, incrementally: the native core, tests and CLI (g++), the wasm
// module (Emscripten), and the TypeScript library and CLI (tsc) into dist/.
import { execSync } from 'node:child_process';
import { chmodSync, cpSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
const run = (cmd, env = {}) => execSync(cmd, { cwd: root, stdio: 'inherit', env: { ...process.env, ...env } });
// Emscripten's JS optimizer needs Debian's acorn (TOOLCHAIN.md).
const emenv = { NODE_PATH: '/usr/share/nodejs' };

function copyIfChanged(from, to) {
  const data = readFileSync(from);
  if (existsSync(to) && readFileSync(to).equals(data)) return;
  writeFileSync(to, data);
}

// One build at a time in this tree (ninja runs on one build folder must not overlap).
const lock = `${root}/build/.lock`;
mkdirSync(`${root}/build`, { recursive: true });
for (let waited = 0; ; waited += 1) {
  try {
    mkdirSync(lock);
    break;
  } catch {
    if (waited > 900) throw new Error(`build: ${lock} held for 15 minutes; remove it if no build is running`);
    execSync('sleep 1');
  }
}
process.on('exit', () => rmSync(lock, { recursive: true, force: true }));

const native = `${root}/build/native`, wasm = `${root}/build/wasm`;
if (!existsSync(`${native}/build.ninja`)) run(`cmake -S . -B build/native -G Ninja -DCMAKE_BUILD_TYPE=Release`);
run(`ninja -C build/native`);
if (!existsSync(`${wasm}/build.ninja`)) {
  run(`emcmake cmake -S . -B build/wasm -G Ninja -DCMAKE_BUILD_TYPE=Release`, emenv);
}
run(`ninja -C build/wasm`, emenv);

mkdirSync(`${root}/web/src/wasm`, { recursive: true });
for (const f of ['hodt.mjs', 'hodt.wasm']) copyIfChanged(`${wasm}/${f}`, `${root}/web/src/wasm/${f}`);
// THIRD_PARTY_NOTICES and package.json's license follow what the wasm was built from.
run('node scripts/notices.mjs');
// A clean dist/: a deleted source must not leave a stale file in the package.
rmSync(`${root}/dist`, { recursive: true, force: true });
run(`npx tsc -p tsconfig.json`);
mkdirSync(`${root}/dist/wasm`, { recursive: true });
for (const f of ['hodt.mjs', 'hodt.wasm', 'hodt.d.mts']) copyIfChanged(`${root}/web/src/wasm/${f}`, `${root}/dist/wasm/${f}`);
chmodSync(`${root}/dist/cli.js`, 0o755);
// The demo as a static site (relative paths), also shipped for `npx hodt demo`.
run(`npx vite build --config web/demo/vite.config.ts --logLevel warn`);
cpSync(`${root}/build/demo`, `${root}/dist/demo`, { recursive: true });
