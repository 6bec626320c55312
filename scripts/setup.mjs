// Installs what is missing, and nothing else: Debian packages (TOOLCHAIN.md) and
// npm packages. Quick and silent when everything is there. Node builtins only:
// this runs before `npm install`.
import { execSync, spawnSync } from 'node:child_process';
import { existsSync, statSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
// (clang-14 and its runtime libraries: the sanitizer build and libFuzzer.)
const DEBIAN = ['cmake', 'ninja-build', 'g++', 'ccache', 'emscripten', 'libcgal-dev', 'libboost-dev', 'doctest-dev', 'libfast-float-dev', 'chromium', 'clang-14', 'libclang-rt-14-dev'];

function installed(pkg) {
  const r = spawnSync('dpkg-query', ['-W', '-f=${Status}', pkg], { encoding: 'utf8' });
  return r.status === 0 && r.stdout.includes('install ok installed');
}

const missing = DEBIAN.filter((p) => !installed(p));
if (missing.length) {
  const sudo = process.getuid?.() === 0 ? '' : 'sudo ';
  console.log(`setup: installing Debian packages: ${missing.join(' ')}`);
  const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
  execSync(`${sudo}apt-get update -qq`, { stdio: 'inherit', env });
  execSync(`${sudo}apt-get install -y -qq --no-install-recommends ${missing.join(' ')}`, { stdio: 'inherit', env });
}

// npm packages: install when node_modules is missing or older than the lock file.
const lock = `${root}/package-lock.json`;
const stamp = `${root}/node_modules/.package-lock.json`;
if (!existsSync(stamp) || (existsSync(lock) && statSync(lock).mtimeMs > statSync(stamp).mtimeMs)) {
  console.log('setup: installing npm packages');
  execSync('npm install --no-audit --no-fund', { cwd: root, stdio: 'inherit' });
}
