// The loader fuzzer: mutated GIS fixtures (mutate.mjs) through hodt/loaders in
// worker processes (worker.mjs), each file bounded in time (10 s) and the worker
// in memory (1 GiB resident); a sample of them through the npm CLI as well, which
// must exit 0 with JSON or exit 2 with exactly one printable line. Findings are
// written to build/fuzz/loaders/findings.json, each with the seed that replays it:
//
//   node tests/fuzz/loaders/worker.mjs SEED SEED+1
//
// Run as a script: node tests/fuzz/loaders/fuzz.mjs [FILES] [FIRST_SEED]
import { fork, spawnSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { fileURLToPath } from 'node:url';
import { mutate } from './mutate.mjs';

const root = fileURLToPath(new URL('../../../', import.meta.url));
const out = `${root}build/fuzz/loaders`;
const TIME_LIMIT_MS = 10_000;
const MEMORY_LIMIT = 1 << 30;

function residentBytes(pid) {
  try {
    const kb = /VmRSS:\s+(\d+)/.exec(readFileSync(`/proc/${pid}/status`, 'utf8'))?.[1];
    return kb ? Number(kb) * 1024 : 0;
  } catch {
    return 0;
  }
}

// Seeds [from, to) in one worker process after another (a new one after a kill).
function runRange(from, to, stats) {
  return new Promise((resolve) => {
    let seed = from;
    let started = Date.now();
    const start = () => {
      if (seed >= to) return resolve();
      const child = fork(`${root}tests/fuzz/loaders/worker.mjs`, [String(seed), String(to)], { stdio: ['ignore', 'ignore', 'pipe', 'ipc'] });
      let stderr = '';
      child.stderr.on('data', (d) => (stderr += d));
      let current = null; // the seed being read
      let killed = null;
      started = Date.now();
      const finish = () => {
        if (current === null) return;
        stats.runs += 1;
        stats.slowest = Math.max(stats.slowest, Date.now() - started);
      };
      const watch = setInterval(() => {
        const rss = residentBytes(child.pid);
        stats.maxRss = Math.max(stats.maxRss, rss);
        if (current !== null && Date.now() - started > TIME_LIMIT_MS) killed = `took over ${TIME_LIMIT_MS / 1000} s`;
        else if (rss > MEMORY_LIMIT) killed = `reached ${(rss / 2 ** 20).toFixed(0)} MiB resident`;
        if (killed) child.kill('SIGKILL');
      }, 100);
      child.on('message', (m) => {
        if (m.finding) stats.findings.push(m);
        else {
          finish();
          current = m.done ? null : m.seed;
          started = Date.now();
          if (m.done) seed = to;
        }
      });
      child.on('exit', (code, signal) => {
        clearInterval(watch);
        if (current !== null) {
          const m = mutate(current);
          const why = killed ?? `the worker died (exit ${code}, signal ${signal}): ${stderr.trim().split('\n').slice(-3).join(' | ').slice(0, 300)}`;
          stats.findings.push({ seed: current, finding: why, fixture: m.name, what: m.what });
          stats.runs += 1;
          seed = current + 1;
        } else if (seed < to) {
          stats.findings.push({ seed, finding: `the worker exited early (exit ${code}): ${stderr.trim().slice(0, 300)}` });
          seed = to;
        }
        start();
      });
    };
    start();
  });
}

// One mutated file through the npm CLI: exit 0 with a JSON document, or exit 2
// with exactly one printable line on stderr and nothing on stdout.
function cliCheck(seed, dir) {
  const m = mutate(seed);
  const file = `${dir}/${seed}-${m.name}`;
  writeFileSync(file, m.bytes);
  const r = spawnSync('node', [`${root}dist/cli.js`, 'stats', file], { encoding: 'utf8', timeout: 30_000 });
  const lines = r.stderr.split('\n').filter(Boolean);
  let finding = null;
  if (r.error || r.status === null) finding = `the CLI did not finish (${r.error?.message ?? r.signal})`;
  else if (r.status === 0) {
    try {
      JSON.parse(r.stdout);
      if (m.mustRefuse) finding = `the CLI read it (exit 0) although ${m.what}`;
    } catch {
      finding = 'exit 0 without a JSON document';
    }
  } else if (r.status !== 2) finding = `exit ${r.status}: ${lines.slice(-2).join(' | ').slice(0, 300)}`;
  else if (lines.length !== 1 || !/^[\x20-\x7e]+$/.test(lines[0]) || r.stdout !== '')
    finding = `exit 2 with ${lines.length} stderr lines: ${JSON.stringify(r.stderr.slice(0, 300))}`;
  rmSync(file, { force: true });
  return finding ? { seed, finding, fixture: m.name, what: m.what, via: 'cli' } : null;
}

/** Fuzzes `files` mutated files from seed `first` (spread over the cores), and
 * `cliFiles` of them also through the npm CLI. */
export async function fuzzLoaders({ files = 20_000, first = 0, cliFiles = 20, workers = Math.max(1, availableParallelism()) } = {}) {
  const t0 = Date.now();
  const stats = { runs: 0, findings: [], slowest: 0, maxRss: 0 };
  const per = Math.ceil(files / workers);
  await Promise.all(Array.from({ length: workers }, (_, w) => runRange(first + w * per, first + Math.min(files, (w + 1) * per), stats)));
  mkdirSync(`${out}/cli`, { recursive: true });
  let cliRuns = 0;
  for (let i = 0; i < cliFiles; ++i) {
    const seed = first + Math.floor(((i + 0.5) * files) / cliFiles);
    const finding = cliCheck(seed, `${out}/cli`);
    cliRuns += 1;
    if (finding) stats.findings.push(finding);
  }
  stats.seconds = (Date.now() - t0) / 1000;
  stats.cliRuns = cliRuns;
  writeFileSync(`${out}/findings.json`, JSON.stringify(stats.findings, null, 1));
  return stats;
}

export function describe(stats) {
  return (
    `fuzz: loaders: ${stats.runs.toLocaleString('en')} mutated GIS files in ${stats.seconds.toFixed(0)} s (${stats.cliRuns} also through the npm CLI), ` +
    `slowest ${stats.slowest} ms, largest worker ${(stats.maxRss / 2 ** 20).toFixed(0)} MiB resident, ` +
    (stats.findings.length ? `${stats.findings.length} FINDINGS (build/fuzz/loaders/findings.json)` : 'no findings')
  );
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const [files, first] = process.argv.slice(2).map(Number);
  const stats = await fuzzLoaders({ files: files || 20_000, first: first || 0, cliFiles: Math.min(200, Math.ceil((files || 20_000) / 1000)) });
  for (const f of stats.findings.slice(0, 20)) console.log(`seed ${f.seed} (${f.fixture}, ${f.what}${f.via ? ', CLI' : ''}): ${f.finding}`);
  console.log(describe(stats));
  process.exitCode = stats.findings.length ? 1 : 0;
}
