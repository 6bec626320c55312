// The CLI end to end (read the text file, build, solve, write the JSON), native
// (build/native/hodt) against wasm (`node dist/cli.js`, what `npx hodt` runs), on a
// 1000 x 1000 DEM grid in projected coordinates written as a GIS export would
// (7 decimals), and `stats` against one solve. Wall time of the whole process,
// the fastest of `runs`.
import { spawnSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';

export function runCliEndToEnd({ root, tmp, log, quick }) {
  const w = quick ? 300 : 1000, runs = quick ? 1 : 2;
  const lines = [];
  for (let j = 0; j < w; ++j)
    for (let i = 0; i < w; ++i) {
      const z = 300 + 120 * Math.sin(i / 37) * Math.cos(j / 23) + 0.37 * ((i * 7919 + j * 104729) % 101);
      lines.push(`${(731012.3456789 + 74.98765 * i).toFixed(7)} ${(5501234.5 + 74.98765 * j).toFixed(7)} ${z.toFixed(3)}`);
    }
  const file = join(tmp, 'utm-grid.txt');
  writeFileSync(file, lines.join('\n') + '\n');
  const clis = { native: [join(root, 'build/native/hodt')], wasm: ['node', join(root, 'dist/cli.js')] };
  const fastest = (cli, args) => {
    let best = Infinity;
    for (let r = 0; r < runs; ++r) {
      const t0 = performance.now();
      const p = spawnSync(cli[0], [...cli.slice(1), ...args], { encoding: 'utf8', maxBuffer: 1 << 30 });
      if (p.status !== 0) throw new Error(`${cli.join(' ')} ${args.join(' ')}: ${p.stderr}`);
      best = Math.min(best, performance.now() - t0);
    }
    return best;
  };
  const solve = ['solve', file, '--objective', 'min-local-minima', '--output', join(tmp, 'solution.json')];
  const out = { points: w * w };
  for (const [name, cli] of Object.entries(clis)) out[name] = { solveMs: fastest(cli, solve), statsMs: fastest(cli, ['stats', file]) };
  out.solveWasmOverNative = out.wasm.solveMs / out.native.solveMs;
  out.statsOverSolveWasm = out.wasm.statsMs / out.wasm.solveMs;
  log(`\nCLI end to end, ${w * w} points of a UTM DEM grid (read text, build, solve min-local-minima, write the solution JSON):`);
  log(`  native ${(out.native.solveMs / 1000).toFixed(2)} s, wasm ${(out.wasm.solveMs / 1000).toFixed(2)} s: wasm / native ${out.solveWasmOverNative.toFixed(2)}x`);
  log(`  stats: native ${(out.native.statsMs / 1000).toFixed(2)} s, wasm ${(out.wasm.statsMs / 1000).toFixed(2)} s: wasm stats / wasm solve ${out.statsOverSolveWasm.toFixed(2)}x`);
  return out;
}
