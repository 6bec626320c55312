// Runs every test suite: doctest (native core), Vitest (the wasm library and CLI in
// Node), and the browser tests (Playwright driving Debian's Chromium). Prints one
// closing line "tests: N passed, M failed".
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
mkdirSync(`${root}/test-results`, { recursive: true });
let passed = 0, failed = 0;
// The failing tests' names, repeated above the closing line so that the end of
// a long log says what failed.
const failures = [];
// doctest cases left out under the sanitizers: the long brute-force and
// order-k sweeps (seconds natively, up to ten minutes there) and the three that
// time progress and cancellation. The native run has them all.
const SANITIZER_SKIP = [
  'heuristic at order k*', 'heuristic bounds at order k*', 'large instances*', 'exact k-OD optimisation*',
  'exact at order k equals*', 'near-degenerate: solves*', 'fill DP: the best*', 'long regions*',
  'bounds every triangulation*', 'progress comes*', 'cancelling*', 'wheels*', 'forced edges*', 'baker at order k*',
  'star bound: sums only*', 'optimum invariant*', 'orders 5 to 8*', 'tiny region budgets*',
  'domain: rasters with holes*', 'domain: the vertices\' fans*',
];

function run(title, cmd, args) {
  console.log(`\n== ${title}`);
  const r = spawnSync(cmd, args, { cwd: root, stdio: 'inherit' });
  return r.status ?? 1;
}

// doctest: the console shows progress, the JUnit report gives the counts.
function doctest(title, binary, report, extra = []) {
  const status = run(title, binary, ['--reporters=console,junit', `--out=${root}/test-results/${report}`, '--no-intro=true', ...extra]);
  const xml = existsSync(`${root}/test-results/${report}`) ? readFileSync(`${root}/test-results/${report}`, 'utf8') : '';
  const cases = (xml.match(/<testcase /g) ?? []).length;
  const bad = (xml.match(/<failure/g) ?? []).length;
  for (const m of xml.matchAll(/<testcase [^>]*name="([^"]*)"[^>]*>\s*<failure/g)) failures.push(`${title}: ${m[1]}`);
  if (cases) {
    passed += cases - bad;
    failed += bad;
  } else failed += status === 0 ? 0 : 1;
  if (status !== 0 && !bad) {
    failed += 1;
    failures.push(`${title}: exit ${status}`);
  }
}
doctest('doctest (native core)', `${root}/build/native/hodt_tests`, 'doctest.xml');

function vitest(title, config, report) {
  const status = run(title, 'npx', ['vitest', 'run', '--config', config, '--reporter=default', '--reporter=json', `--outputFile.json=${root}/test-results/${report}`]);
  const file = `${root}/test-results/${report}`;
  if (existsSync(file)) {
    const j = JSON.parse(readFileSync(file, 'utf8'));
    passed += j.numPassedTests;
    failed += j.numFailedTests;
    for (const suite of j.testResults ?? []) {
      const file = suite.name.replace(root, '');
      for (const t of suite.assertionResults ?? []) if (t.status === 'failed') failures.push(`${title}: ${file}: ${t.fullName}`);
      if (suite.status === 'failed' && !(suite.assertionResults ?? []).some((t) => t.status === 'failed')) failures.push(`${title}: ${file}: failed to load`);
    }
    if (status !== 0 && j.numFailedTests === 0) failed += 1; // a suite failed to load
  } else if (status !== 0) {
    failed += 1;
    failures.push(`${title}: exit ${status}`);
  }
}
vitest('vitest (library and CLI, real wasm in Node)', 'vitest.config.ts', 'vitest.json');
vitest('browser (Playwright + Chromium)', 'tests/e2e/vitest.config.ts', 'e2e.json');
vitest('npm package (pack, offline install, Node, CLI, types, Vite + Chromium under CSP)', 'tests/pack/vitest.config.ts', 'pack.json');

// Sanitizers: the core built by clang with AddressSanitizer and
// UndefinedBehaviorSanitizer (build/sanitize, incremental), its doctest suite but
// for the long brute-force sweeps (the native run has them), and a short run of
// every fuzzer (scripts/fuzz.mjs runs them as long as asked).
{
  const { buildSanitized, fuzz, FUZZ_TARGETS } = await import('./fuzz.mjs');
  console.log('\n== sanitizer build (clang, ASan + UBSan)');
  let built = true;
  try {
    buildSanitized();
  } catch {
    built = false;
    failed += 1;
    failures.push('sanitizer build');
  }
  if (built) {
    doctest('doctest (ASan + UBSan)', `${root}/build/sanitize/hodt_tests`, 'doctest-sanitize.xml', [`--test-case-exclude=${SANITIZER_SKIP.join(',')}`]);
    for (const target of FUZZ_TARGETS) {
      const r = fuzz(target, 20);
      console.log(`fuzz: ${target}: ${r.runs.toLocaleString('en')} inputs in 20 s, ${r.ok ? 'no findings' : 'FINDING'}`);
      if (r.ok) passed += 1;
      else {
        failed += 1;
        failures.push(`fuzz: ${target}`);
      }
    }
  }
}

if (failures.length) console.log(`\nfailed:\n${failures.map((f) => `  ${f}`).join('\n')}`);
console.log(`\ntests: ${passed} passed, ${failed} failed`);
process.exitCode = failed ? 1 : 0;
