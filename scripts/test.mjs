// Runs every test suite: doctest (native core), Vitest (the wasm library and CLI in
// Node), and the browser tests (Playwright driving Debian's Chromium). Prints one
// closing line "tests: N passed, M failed".
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
mkdirSync(`${root}/test-results`, { recursive: true });
let passed = 0, failed = 0;

function run(title, cmd, args) {
  console.log(`\n== ${title}`);
  const r = spawnSync(cmd, args, { cwd: root, stdio: 'inherit' });
  return r.status ?? 1;
}

// doctest: the console shows progress, the JUnit report gives the counts.
{
  const status = run('doctest (native core)', `${root}/build/native/hodt_tests`, [
    '--reporters=console,junit', `--out=${root}/test-results/doctest.xml`, '--no-intro=true',
  ]);
  const xml = existsSync(`${root}/test-results/doctest.xml`) ? readFileSync(`${root}/test-results/doctest.xml`, 'utf8') : '';
  const cases = (xml.match(/<testcase /g) ?? []).length;
  const bad = (xml.match(/<failure/g) ?? []).length;
  if (cases) {
    passed += cases - bad;
    failed += bad;
  } else failed += status === 0 ? 0 : 1;
  if (status !== 0 && !bad) failed += 1;
}

function vitest(title, config, report) {
  const status = run(title, 'npx', ['vitest', 'run', '--config', config, '--reporter=default', '--reporter=json', `--outputFile.json=${root}/test-results/${report}`]);
  const file = `${root}/test-results/${report}`;
  if (existsSync(file)) {
    const j = JSON.parse(readFileSync(file, 'utf8'));
    passed += j.numPassedTests;
    failed += j.numFailedTests;
    if (status !== 0 && j.numFailedTests === 0) failed += 1; // a suite failed to load
  } else if (status !== 0) failed += 1;
}
vitest('vitest (library and CLI, real wasm in Node)', 'vitest.config.ts', 'vitest.json');
vitest('browser (Playwright + Chromium)', 'tests/e2e/vitest.config.ts', 'e2e.json');
vitest('npm package (pack, offline install, Node, CLI, types, Vite + Chromium under CSP)', 'tests/pack/vitest.config.ts', 'pack.json');

console.log(`\ntests: ${passed} passed, ${failed} failed`);
process.exitCode = failed ? 1 : 0;
