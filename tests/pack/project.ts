// A temporary project with the packed package installed, as a user would have it.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

export const repo = fileURLToPath(new URL('../../', import.meta.url));

export interface PackedFile {
  path: string;
  size: number;
  mode: number;
}

export interface Project {
  /** The temporary project folder (package.json, node_modules/hodt). */
  dir: string;
  /** The tarball npm pack made. */
  tarball: string;
  /** What the tarball holds. */
  files: PackedFile[];
  remove(): void;
}

/** Fails early, with the fix, when dist/ is missing or older than web/src. */
export function checkBuilt(): void {
  const missing = ['dist/index.js', 'dist/three.js', 'dist/wasm/hodt.wasm', 'dist/wasm/hodt.mjs'].filter((f) => !existsSync(join(repo, f)));
  if (missing.length) throw new Error(`${missing.join(', ')} missing: run \`npm run build\` first`);
  for (const f of readdirSync(join(repo, 'web/src'))) {
    if (!f.endsWith('.ts') || f.endsWith('.d.ts')) continue;
    const out = join(repo, 'dist', f.replace(/\.ts$/, '.js'));
    if (!existsSync(out) || statSync(out).mtimeMs < statSync(join(repo, 'web/src', f)).mtimeMs) {
      throw new Error(`dist is older than web/src/${f}: run \`npm run build\` first`);
    }
  }
  for (const f of ['hodt.wasm', 'hodt.mjs']) {
    if (!readFileSync(join(repo, 'web/src/wasm', f)).equals(readFileSync(join(repo, 'dist/wasm', f)))) {
      throw new Error(`dist/wasm/${f} differs from web/src/wasm/${f}: run \`npm run build\` first`);
    }
  }
}

const run = (cmd: string, args: string[], cwd: string) => execFileSync(cmd, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });

/** npm pack in the repository, then npm install of the tarball in an empty project. */
export function packAndInstall(): Project {
  const dir = mkdtempSync(join(tmpdir(), 'hodt-pack-'));
  const packs = join(dir, 'packs');
  mkdirSync(packs);
  const [info] = JSON.parse(run('npm', ['pack', '--json', '--pack-destination', packs], repo)) as {
    filename: string;
    files: PackedFile[];
  }[];
  const tarball = join(packs, info!.filename);
  const project = join(dir, 'project');
  mkdirSync(project);
  writeFileSync(join(project, 'package.json'), JSON.stringify({ name: 'hodt-smoke', private: true, type: 'module' }, null, 2));
  // --prefer-offline: the dependencies (the loaders' geotiff and laz-perf) come from
  // npm's cache, which the repository's own install filled; the registry only if not.
  run('npm', ['install', '--no-audit', '--no-fund', '--prefer-offline', tarball], project);
  return { dir: project, tarball, files: info!.files, remove: () => rmSync(dir, { recursive: true, force: true }) };
}

/** Makes packages of the repository's node_modules visible in the project
 * (three, type packages) without a network install. Call after npm install,
 * which would remove them. */
export function linkFromRepo(project: string, names: string[]): void {
  for (const name of names) {
    const to = join(project, 'node_modules', name);
    if (existsSync(to)) continue;
    mkdirSync(dirname(to), { recursive: true });
    symlinkSync(join(repo, 'node_modules', name), to, 'dir');
  }
}
