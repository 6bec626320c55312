// The sanitizer build and the fuzzers (libFuzzer, clang, AddressSanitizer and
// UndefinedBehaviorSanitizer): builds build/sanitize incrementally, then runs each
// target of tests/fuzz for the given seconds on its corpus in build/fuzz/ (seeded
// from the test fixtures, kept between runs), and reports executions and findings.
//
//   node scripts/fuzz.mjs [SECONDS_PER_TARGET] [TARGET...]   (npm run fuzz -- 600)
//   node scripts/fuzz.mjs --build-only
//   node scripts/fuzz.mjs loaders [FILES] [FIRST_SEED]        (npm run fuzz -- loaders 1000000)
//
// `loaders` runs the loader fuzzer instead (tests/fuzz/loaders/fuzz.mjs): FILES
// mutated GIS fixtures (default 200,000) through hodt/loaders of dist/ (npm run
// build first) and a sample of them through the npm CLI.
//
// A finding stops that target, leaves its input in build/fuzz/artifacts/ and makes
// the exit code 1. Print the reproducer with: build/sanitize/fuzz_X ARTIFACT
import { execSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
const dir = `${root}build/sanitize`;
const args = process.argv.slice(2);
const buildOnly = args.includes('--build-only');
const seconds = Number(args.find((a) => /^\d+$/.test(a)) ?? 20);
export const FUZZ_TARGETS = ['fuzz_cli', 'fuzz_solve', 'fuzz_edit'];
const targets = FUZZ_TARGETS;
const chosen = args.filter((a) => targets.includes(a));

export function buildSanitized() {
  // One build at a time per folder (scripts/build.mjs holds build/.lock for its own).
  const compiler = existsSync('/usr/bin/clang++-14') ? 'clang++-14' : 'clang++';
  if (!existsSync(`${dir}/build.ninja`)) {
    execSync(`cmake -S . -B build/sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHODT_SANITIZE=ON -DCMAKE_CXX_COMPILER=${compiler}`, {
      cwd: root,
      stdio: 'inherit',
    });
  }
  execSync(`ninja -C build/sanitize hodt_tests ${targets.join(' ')}`, { cwd: root, stdio: 'inherit' });
}

// Seeds: every fixture as a CLI input (under each mode byte), and a few bytes for
// the others (libFuzzer grows them).
function seed(target, corpus) {
  mkdirSync(corpus, { recursive: true });
  if (readdirSync(corpus).length) return;
  const fixtures = ['tests/fixtures', 'tests/fixtures-gis']
    .flatMap((d) => readdirSync(`${root}${d}`).map((f) => `${root}${d}/${f}`))
    .filter((f) => /\.(csv|txt|json|asc)$/.test(f) && readFileSync(f).length < 20000);
  let i = 0;
  if (target === 'fuzz_cli') {
    for (const f of fixtures) for (const mode of [0, 1, 2, 9]) writeFileSync(`${corpus}/seed-${i++}`, Buffer.concat([Buffer.from([mode, i & 255]), readFileSync(f)]));
  } else {
    for (let s = 0; s < 32; ++s) writeFileSync(`${corpus}/seed-${i++}`, Buffer.from(Array.from({ length: 48 }, (_, j) => (s * 37 + j * 11) & 255)));
  }
}

export function fuzz(target, secs) {
  const corpus = `${root}build/fuzz/corpus/${target}`;
  const artifacts = `${root}build/fuzz/artifacts/`;
  seed(target, corpus);
  mkdirSync(artifacts, { recursive: true });
  const r = spawnSync(
    `${dir}/${target}`,
    [corpus, `-max_total_time=${secs}`, '-max_len=2048', '-timeout=20', '-rss_limit_mb=3000', `-artifact_prefix=${artifacts}`, '-print_final_stats=1'],
    { cwd: root, encoding: 'utf8', env: { ...process.env, ASAN_OPTIONS: 'detect_leaks=1', UBSAN_OPTIONS: 'print_stacktrace=1' } },
  );
  const runs = Number(/stat::number_of_executed_units:\s*(\d+)/.exec(r.stderr)?.[1] ?? 0);
  const ok = r.status === 0;
  if (!ok) process.stderr.write(r.stderr.split('\n').slice(-60).join('\n') + '\n');
  return { target, runs, ok };
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1] && args[0] === 'loaders') {
  const { describe, fuzzLoaders } = await import('../tests/fuzz/loaders/fuzz.mjs');
  const files = Number(args[1] ?? 200_000);
  const stats = await fuzzLoaders({ files, first: Number(args[2] ?? 0), cliFiles: Math.min(1000, Math.ceil(files / 1000)) });
  for (const f of stats.findings.slice(0, 50)) console.log(`seed ${f.seed} (${f.fixture}, ${f.what}${f.via ? ', CLI' : ''}): ${f.finding}`);
  console.log(describe(stats));
  process.exitCode = stats.findings.length ? 1 : 0;
} else if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  buildSanitized();
  if (!buildOnly) {
    let failed = false;
    for (const t of chosen.length ? chosen : targets) {
      const r = fuzz(t, seconds);
      console.log(`fuzz: ${t}: ${r.runs.toLocaleString('en')} inputs in ${seconds} s, ${r.ok ? 'no findings' : 'FINDING (see above, input in build/fuzz/artifacts/)'}`);
      failed ||= !r.ok;
    }
    process.exitCode = failed ? 1 : 0;
  }
}
