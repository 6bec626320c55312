// The npm package end to end: npm pack, npm install of the tarball in an empty
// project (no network), then Node, the CLI, TypeScript and a bundled page in
// Chromium under a Content-Security-Policy without 'unsafe-eval'.
import { execFileSync, spawn, spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, normalize } from 'node:path';
import { gzipSync } from 'node:zlib';
import { getIssues } from '@placemarkio/check-geojson';
import type { Browser } from 'playwright-core';
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';
import { build, createServer } from 'vite';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { hills } from '../js/randomPoints.js';
import { launch, watchedPage } from './chromium.js';
import { codeBlocks, headingAnchors, linkTargets } from './markdown.js';
import { checkBuilt, linkFromRepo, packAndInstall, type Project, repo } from './project.js';
import { serveStatic } from './serve.js';

const here = join(repo, 'tests/pack');
const fixture = join(repo, 'tests/fixtures/uniform-50.csv');
const tsc = join(repo, 'node_modules/typescript/bin/tsc');
// What a strict production host sends: scripts and wasm from the origin only, no eval.
const CSP = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; worker-src 'self'";
const CSP_WITHOUT_WASM = "default-src 'self'; script-src 'self'; worker-src 'self'";

let project: Project;
let browser: Browser | undefined;

beforeAll(() => {
  checkBuilt();
  project = packAndInstall();
}, 180_000);

afterAll(async () => {
  await browser?.close();
  if (process.env.HODT_KEEP_PACK) console.log(`kept ${project.dir}`);
  else project?.remove();
});

const inProject = (cmd: string, args: string[]) =>
  spawnSync(cmd, args, { cwd: project.dir, encoding: 'utf8', env: { ...process.env, NODE_OPTIONS: '' } });
// More Node binaries to run the Node check with, e.g. HODT_NODES=/opt/node18/bin/node.
const extraNodes = (process.env.HODT_NODES ?? '').split(':').filter(Boolean);

describe('the tarball', () => {
  it('holds the JS, the types, the wasm and the CLI, and nothing else', () => {
    const paths = project.files.map((f) => f.path).sort();
    for (const f of ['package.json', 'README.md', 'CHANGELOG.md', 'LICENSE', 'THIRD_PARTY_NOTICES', 'dist/index.js', 'dist/index.d.ts', 'dist/three.js', 'dist/three.d.ts', 'dist/export.js', 'dist/export.d.ts', 'dist/cli.js', 'dist/wasm/hodt.mjs', 'dist/wasm/hodt.d.mts', 'dist/wasm/hodt.wasm']) {
      expect(paths).toContain(f);
    }
    for (const p of paths) expect(p).toMatch(/^(package\.json|README\.md|CHANGELOG\.md|LICENSE|THIRD_PARTY_NOTICES|docs\/(api|objectives|higher-order)\.md|docs\/drainage-lidar\.svg|dist\/.+\.(js|d\.ts|mjs|d\.mts|wasm)|dist\/demo\/(index\.html|assets\/[\w-]+\.(js|css|wasm)))$/);
    expect(paths).toContain('dist/demo/index.html');
    const cli = project.files.find((f) => f.path === 'dist/cli.js')!;
    expect(cli.mode & 0o111).not.toBe(0);
  });

  it('every export and the bin point at packed files', () => {
    const pkg = JSON.parse(readFileSync(join(project.dir, 'node_modules/hodt/package.json'), 'utf8'));
    const targets: string[] = [];
    const collect = (v: unknown): void => {
      if (typeof v === 'string') targets.push(v);
      else if (v && typeof v === 'object') Object.values(v).forEach(collect);
    };
    collect(pkg.exports);
    collect(pkg.bin);
    const paths = new Set(project.files.map((f) => `./${f.path}`));
    for (const t of targets) expect(paths, t).toContain(t.startsWith('./') ? t : `./${t}`);
    expect(pkg.type).toBe('module');
    expect(pkg.sideEffects).toBe(false);
  });

  it('hodt/export is an entry of its own: the main entry imports none of it at run time', () => {
    const imports = (f: string): string[] => {
      const text = readFileSync(join(project.dir, 'node_modules/hodt/dist', f), 'utf8');
      const found = [...text.matchAll(/^(?:import|export)\b[^'"]*?from\s*['"](\.[^'"]+)['"]/gm)].map((m) => m[1]!);
      return found.flatMap((s) => [s, ...imports(join(f, '..', s))]);
    };
    const reached = imports('index.js');
    expect(reached).toContain('./load.js');
    expect(reached.filter((s) => /export/.test(s))).toEqual([]);
    expect(imports('export.js').filter((s) => /wasm|index|terrain/.test(s))).toEqual([]);
  });

  it('has no eval or new Function (a page can forbid unsafe-eval)', () => {
    for (const f of project.files.filter((f) => /\.(m?js)$/.test(f.path))) {
      const text = readFileSync(join(project.dir, 'node_modules/hodt', f.path), 'utf8');
      expect(text, f.path).not.toMatch(/new Function\s*\(|\beval\s*\(/);
    }
  });

  // The library's own modules import only each other; the opt-in loaders also
  // their two dependencies, and nothing else (never three or Node built-ins).
  const importsOf = (path: string) => {
    const text = readFileSync(join(project.dir, 'node_modules/hodt', path), 'utf8');
    return [...text.matchAll(/(?:^|[\s;])(?:import|export)\b[^'"]*?from\s*['"]([^'"]+)['"]|import\(\s*['"]([^'"]+)['"]/gm)].map((m) => (m[1] ?? m[2])!);
  };
  it('the library never imports three or Node built-ins statically (the CLI and its demo server may)', () => {
    const cli = ['dist/cli.js', 'dist/demoServer.js'];
    for (const f of project.files.filter((f) => f.path.endsWith('.js') && !cli.includes(f.path))) {
      const allowed = f.path.startsWith('dist/loaders/') ? /^(\.\.?\/|geotiff$|laz-perf$)/ : /^\.\.?\//;
      for (const s of importsOf(f.path)) expect(s, `${f.path} imports ${s}`).toMatch(allowed);
    }
  });

  it('the core entry never reaches the loaders (they do not grow its bundle)', () => {
    const seen = new Set<string>();
    const visit = (path: string) => {
      if (seen.has(path)) return;
      seen.add(path);
      for (const s of importsOf(path)) if (s.startsWith('.')) visit(join(dirname(path), s));
    };
    visit('dist/index.js');
    expect(seen.size).toBeGreaterThan(3);
    expect([...seen].filter((p) => p.includes('loaders'))).toEqual([]);
  });
});

// The package as a company's license review and a reader on npm see it.
describe('license, notices and metadata', () => {
  const shipped = (f: string) => readFileSync(join(project.dir, 'node_modules/hodt', f), 'utf8');
  it('LICENSE is the MIT license of the hodt authors', () => {
    expect(shipped('LICENSE')).toMatch(/^MIT License\n\nCopyright \(c\) the hodt authors\n\nPermission is hereby granted, free of charge/);
  });
  it('THIRD_PARTY_NOTICES and the license field are what scripts/notices.mjs writes from the build and node_modules', () => {
    const r = spawnSync('node', [join(repo, 'scripts/notices.mjs'), '--check'], { encoding: 'utf8' });
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(shipped('THIRD_PARTY_NOTICES')).toBe(readFileSync(join(repo, 'THIRD_PARTY_NOTICES'), 'utf8'));
  });
  it('THIRD_PARTY_NOTICES lists exactly the npm packages installed with hodt, each with a license', () => {
    // Every package in the project's node_modules but hodt itself (nested ones too).
    const installed: string[] = [];
    const visit = (dir: string) => {
      if (!existsSync(dir)) return;
      for (const name of readdirSync(dir)) {
        if (name.startsWith('.')) continue;
        if (name.startsWith('@')) {
          for (const sub of readdirSync(join(dir, name))) visitPackage(join(dir, name, sub));
        } else visitPackage(join(dir, name));
      }
    };
    const visitPackage = (at: string) => {
      const pkg = JSON.parse(readFileSync(join(at, 'package.json'), 'utf8'));
      if (pkg.name !== 'hodt') installed.push(`${pkg.name}@${pkg.version}`);
      visit(join(at, 'node_modules'));
    };
    visit(join(project.dir, 'node_modules'));
    const text = shipped('THIRD_PARTY_NOTICES');
    const section = text.slice(text.indexOf('npm packages installed with hodt'), text.indexOf('npm packages bundled in the demo'));
    const listed = [...section.matchAll(/^npm package: (\S+)\nLicense: (.+)$/gm)];
    expect(listed.map((m) => m[1]).sort()).toEqual(installed.sort());
    expect(installed.length).toBeGreaterThanOrEqual(2);
    for (const m of listed) expect(m[2], m[1]).not.toBe('(none given)');
  });
  it('THIRD_PARTY_NOTICES gives the LGPL and GPL texts and says how to relink the wasm; the README says what the wasm contains', () => {
    const text = shipped('THIRD_PARTY_NOTICES');
    expect(text).toContain('GNU LESSER GENERAL PUBLIC LICENSE\n                       Version 3, 29 June 2007');
    expect(text).toContain('GNU GENERAL PUBLIC LICENSE\n                       Version 3, 29 June 2007');
    expect(text).toContain('Boost Software License - Version 1.0');
    expect(text).toMatch(/Relinking \(LGPL-3\.0 section 4\)[\s\S]*npm run build[\s\S]*loadHodt\(\{ wasmUrl \}\)/);
    expect(text).toMatch(/Filtered_kernel +\d+ headers +LGPL-3\.0-or-later OR LicenseRef-Commercial/);
    const pkg = JSON.parse(shipped('package.json'));
    expect(pkg.license).toMatch(/^MIT AND LGPL-3\.0-or-later AND BSL-1\.0 AND /);
    const readme = shipped('README.md').replace(/\s+/g, ' ');
    expect(readme).toContain(pkg.license);
    for (const part of ['CGAL', 'LGPL-3.0-or-later', 'Boost', 'BSL-1.0', 'Emscripten', '[THIRD_PARTY_NOTICES](THIRD_PARTY_NOTICES)', '[LICENSE](LICENSE)']) expect(readme).toContain(part);
  });
  it('package.json names the repository, its README as homepage and its issues as bugs', () => {
    const pkg = JSON.parse(shipped('package.json'));
    expect(pkg.repository).toEqual({ type: 'git', url: 'git+https://github.com/hodt-project/hodt.git' });
    expect(pkg.homepage).toBe('https://github.com/hodt-project/hodt#readme');
    expect(pkg.bugs).toEqual({ url: 'https://github.com/hodt-project/hodt/issues' });
  });
  it('every relative link of every shipped Markdown file resolves inside the package, anchors included', () => {
    const files = new Set(project.files.map((f) => f.path));
    const markdown = [...files].filter((f) => f.endsWith('.md'));
    expect(markdown).toEqual(expect.arrayContaining(['README.md', 'docs/api.md']));
    let checked = 0;
    for (const doc of markdown) {
      for (const target of linkTargets(shipped(doc))) {
        if (/^(https?:|mailto:)/.test(target)) continue;
        const [path, anchor] = target.split('#') as [string, string | undefined];
        const resolved = path ? normalize(join(dirname(doc), decodeURI(path))) : doc;
        expect(files.has(resolved), `${doc}: ${target} is not in the package`).toBe(true);
        if (anchor !== undefined && resolved.endsWith('.md')) {
          expect(headingAnchors(shipped(resolved)).has(anchor), `${doc}: ${target}: no such heading`).toBe(true);
        }
        ++checked;
      }
    }
    expect(checked).toBeGreaterThan(20);
  });
});

describe('Node', () => {
  beforeAll(() => cpSync(join(here, 'node-smoke.mjs'), join(project.dir, 'node-smoke.mjs')));
  it.each(['node', ...extraNodes])('%s imports the package by name and solves a terrain (without three installed)', (node) => {
    const r = inProject(node, ['node-smoke.mjs', fixture]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out.resolved).toBe(join(project.dir, 'node_modules/hodt/dist/index.js'));
    expect(out).toMatchObject({ points: 50, isUint32: true, optimal: true, three: null });
    expect(out.triangles).toBeGreaterThan(50);
    expect(out.value).toBeLessThanOrEqual(out.delaunayValue);
    expect(Object.keys(out.values)).toHaveLength(13);
    for (const v of Object.values(out.values)) expect(Number.isFinite(v)).toBe(true);
    expect(out.aborted).toEqual({ cancelled: true, name: 'AbortError' });
    expect(out.input).toEqual({ input: true, hodt: true, name: 'InputError', message: 'point 2: y is NaN, expected a finite number' });
  });

  it('solveInWorker stops a 30-second solve within a second of AbortSignal.timeout(100)', () => {
    cpSync(join(here, 'cancel.mjs'), join(project.dir, 'cancel.mjs'));
    const points = hills(60, 7); // min-mixed-vertices at order 6: about 30 s (tests/js/solve-in-worker.test.ts)
    writeFileSync(join(project.dir, 'hills.f64'), new Uint8Array(points.buffer));
    const r = inProject('node', ['cancel.mjs', 'hills.f64']);
    expect(r.stderr).toBe('');
    const out = JSON.parse(r.stdout);
    expect(out).toMatchObject({ cancelled: true, name: 'AbortError', cause: 'TimeoutError' });
    expect(out.ms).toBeGreaterThanOrEqual(100);
    expect(out.ms).toBeLessThan(1000);
  });

  it('hodt/three builds a geometry with the project\'s three', () => {
    linkFromRepo(project.dir, ['three']);
    const r = inProject('node', ['node-smoke.mjs', fixture, 'three']);
    expect(r.status, r.stderr).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out.three).toEqual({ isBufferGeometry: true, index: out.triangles * 3, position: 50 });
  });
});

describe('CLI (npm bin)', () => {
  it('npx hodt stats FILE prints the stats JSON', () => {
    const r = inProject('npx', ['--no', 'hodt', 'stats', fixture]);
    expect(r.status, r.stderr).toBe(0);
    const j = JSON.parse(r.stdout);
    expect(j.points).toBe(50);
    expect(Object.keys(j.delaunay)).toHaveLength(13);
  });
  it('npx hodt --version, and --output writes the mesh formats with hodt/export', () => {
    const pkg = JSON.parse(readFileSync(join(repo, 'package.json'), 'utf8'));
    expect(inProject('npx', ['--no', '--', 'hodt', '--version']).stdout).toBe(`hodt ${pkg.version}\n`);
    const r = inProject('npx', ['--no', 'hodt', 'solve', fixture, '--objective', 'min-local-minima', '--output', 'cli.ply', '--output', 'cli.glb', '--output', 'cli.geojson']);
    expect(r.status, r.stderr).toBe(0);
    expect(readFileSync(join(project.dir, 'cli.ply'), 'latin1')).toMatch(/^ply\nformat binary_little_endian 1\.0\n/);
    expect(readFileSync(join(project.dir, 'cli.glb')).readUInt32LE(0)).toBe(0x46546c67);
    expect(JSON.parse(readFileSync(join(project.dir, 'cli.geojson'), 'utf8')).type).toBe('FeatureCollection');
  });
  it('npx hodt reads a GeoTIFF DEM and a LAZ point cloud (the loaders and their dependencies installed)', () => {
    // A UTM DEM with NODATA edges and an inlet: the default domain leaves the
    // hull's slivers outside, so quads flip and the value improves on Delaunay.
    const tif = join(repo, 'tests/fixtures-gis/dem-utm-inlet-nodata.tif');
    const r = inProject('npx', ['--no', 'hodt', 'solve', tif, '--objective', 'minmax-edge-normal-angle', '--triangles', '--output', 'dem.ply', '--output', 'dem.geojson']);
    expect(r.status, r.stderr).toBe(0);
    const solved = JSON.parse(r.stdout);
    expect(solved.value).toBeLessThan(solved.delaunayValue);
    expect(solved.flipped).toBeGreaterThan(0);
    expect(solved.outsideTriangles).toBeGreaterThan(0);
    expect(solved.crs).toBe('EPSG:32633');
    // Standard readers: three's PLYLoader and a GeoJSON validator, with the
    // solution's counts and the file's UTM coordinates.
    const plyBytes = readFileSync(join(project.dir, 'dem.ply'));
    expect(plyBytes.toString('latin1')).toMatch(/\ncomment crs EPSG:32633\n/);
    const mesh = new PLYLoader().parse(plyBytes.buffer.slice(plyBytes.byteOffset, plyBytes.byteOffset + plyBytes.length));
    expect(mesh.getIndex()!.count).toBe(3 * solved.triangles.length);
    expect(mesh.getAttribute('position').count).toBe(1200 - 307); // the cells with data
    expect(mesh.getAttribute('position').getX(0)).toBeGreaterThan(500000);
    const text = readFileSync(join(project.dir, 'dem.geojson'), 'utf8');
    expect(getIssues(text)).toEqual([]);
    const geojson = JSON.parse(text);
    expect(geojson.features).toHaveLength(solved.triangles.length);
    expect(geojson.features.filter((f: { properties: { inside: boolean } }) => !f.properties.inside)).toHaveLength(solved.outsideTriangles);
    expect(geojson.crs.properties.name).toBe('urn:ogc:def:crs:EPSG::32633');
    const laz = inProject('npx', ['--no', 'hodt', 'stats', join(repo, 'tests/fixtures-gis/lidar-point10.laz')]);
    expect(laz.status, laz.stderr).toBe(0);
    expect(JSON.parse(laz.stdout).points).toBe(276);
  });
  it('npx hodt solve reads standard input and reports bad files with exit code 2', () => {
    const ok = spawnSync('npx', ['--no', 'hodt', 'solve', '-', '--objective', 'min-local-minima'], {
      cwd: project.dir,
      encoding: 'utf8',
      input: readFileSync(fixture, 'utf8'),
    });
    expect(ok.status, ok.stderr).toBe(0);
    expect(JSON.parse(ok.stdout)).toMatchObject({ objective: 'min-local-minima', optimal: true });
    const bad = inProject('npx', ['--no', 'hodt', 'stats', join(repo, 'tests/fixtures/bad-nan.csv')]);
    expect(bad.status).toBe(2);
    expect(bad.stderr).toMatch(/bad-nan\.csv/);
  });
});

describe('npx hodt demo', () => {
  it('serves the teaching demo from the installed package: it renders, solves, and a copied link reproduces it', async () => {
    // (Its own process group: npx does not pass a signal on to the server it starts.)
    const child = spawn('npx', ['--no', 'hodt', 'demo', '--port', '0', '--no-open'], { cwd: project.dir, env: { ...process.env, NODE_OPTIONS: '' }, detached: true });
    try {
      const url = await new Promise<string>((resolve, reject) => {
        let out = '';
        child.stdout.on('data', (d: Buffer) => {
          out += d.toString();
          const m = /hodt demo: (http:\/\/\S+)/.exec(out);
          if (m) resolve(m[1]!);
        });
        child.on('exit', (code) => reject(new Error(`hodt demo exited with ${code}: ${out}`)));
      });
      browser ??= await launch();
      const open = async (hash: string) => {
        const w = await watchedPage(browser!);
        await w.page.goto(url + hash);
        await w.page.waitForFunction(() => {
          const h = (window as { __hodt?: { ready: boolean; solving: boolean; solves: number } }).__hodt;
          return h?.ready === true && !h.solving && h.solves > 0;
        }, null, { timeout: 60_000 });
        return w;
      };
      // A malformed address is refused and the server keeps serving.
      expect((await fetch(`${url}%E0%A4%A`)).status).toBe(400);
      expect((await fetch(url)).status).toBe(200);
      const first = await open('');
      const state = () => first.page.evaluate(() => {
        const h = (window as unknown as { __hodt: { pointsCsv(): string; solution: { value: number } | null; link(): string | null } }).__hodt;
        return { points: h.pointsCsv(), value: h.solution?.value, link: h.link() };
      });
      const a = await state();
      expect(a.value).toBeTypeOf('number');
      const second = await open(new URL(a.link!).hash);
      const b = await second.page.evaluate(() => {
        const h = (window as unknown as { __hodt: { pointsCsv(): string; solution: { value: number } | null } }).__hodt;
        return { points: h.pointsCsv(), value: h.solution?.value };
      });
      expect(b).toEqual({ points: a.points, value: a.value });
      expect(first.errors).toEqual([]);
      expect(second.errors).toEqual([]);
      await first.page.close();
      await second.page.close();
    } finally {
      process.kill(-child.pid!, 'SIGINT');
    }
  }, 120_000);

  it('refuses a bad option in one line', () => {
    const r = inProject('npx', ['--no', 'hodt', 'demo', '--port', 'eighty']);
    expect(r.status).toBe(2);
    expect(r.stderr.trim().split('\n').filter((l) => !l.startsWith('npm warn'))).toEqual(["hodt demo: --port needs a port number 0 to 65535, got 'eighty'; usage: hodt demo [--port N] [--no-open] [--help]"]);
  });
});

describe('sizes', () => {
  it('the sizes and counts in the docs are what tests/pack/sizes.mjs measures now', () => {
    const r = spawnSync('node', [join(here, 'sizes.mjs'), '--check'], { encoding: 'utf8' });
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
  });
  it("the shipped docs state the tarball's file count and the shipped wasm's raw and gzipped size", () => {
    const api = readFileSync(join(project.dir, 'node_modules/hodt/docs/api.md'), 'utf8');
    const readme = readFileSync(join(project.dir, 'node_modules/hodt/README.md'), 'utf8');
    const wasm = readFileSync(join(project.dir, 'node_modules/hodt/dist/wasm/hodt.wasm'));
    const kB = (n: number) => `${(n / 1024).toFixed(1)} KiB`;
    expect(/npm tarball: (\d+) files/.exec(api)?.[1]).toBe(String(project.files.length));
    expect(api).toContain(`| \`dist/wasm/hodt.wasm\` | ${kB(wasm.length)} | ${kB(gzipSync(wasm, { level: 9 }).length)} |`);
    expect(/\(wasm (\d+) KiB\)/.exec(readme)?.[1]).toBe(String(Math.round(gzipSync(wasm, { level: 9 }).length / 1024)));
  });
});

describe('TypeScript', () => {
  beforeAll(() => {
    cpSync(join(here, 'examples'), join(project.dir, 'examples'), { recursive: true });
    linkFromRepo(project.dir, ['three', '@types/three', '@types/node']);
  });
  const check = (config: string, extra: string[] = []) => {
    const r = spawnSync('node', [tsc, '-p', `examples/${config}`, ...extra], { cwd: project.dir, encoding: 'utf8' });
    expect(r.stdout + r.stderr).toBe('');
    expect(r.status).toBe(0);
  };
  it('the page\'s examples and the checks of what the types accept compile in strict mode (NodeNext resolution)', () => check('tsconfig.json'));
  it('the same in strict mode (Bundler resolution)', () => check('tsconfig.bundler.json'));
  it('the worker the page runs is the one docs/api.md shows', () => {
    const worker = readFileSync(join(here, 'examples/worker.ts'), 'utf8').replace(/^(\/\/.*\n)+/, '');
    expect(codeBlocks(readFileSync(join(repo, 'docs/api.md'), 'utf8')).map((b) => b.code)).toContain(worker);
  });
  it('a strict project without @types/node, esnext lib or skipLibCheck compiles', () => check('tsconfig.minimal.json'));
  it('a strict Node-only project (lib ES2022, @types/node, no DOM, skipLibCheck off) compiles', () =>
    check('tsconfig.node-only.json'));
});

// Every ts and js block of the README and docs/api.md, as the package ships them,
// written out as files of the project and compiled under "strict" against the
// installed package; the runnable ones are then run.
describe('the examples in the shipped docs', () => {
  const written: { doc: string; file: string; code: string }[] = [];
  beforeAll(() => {
    linkFromRepo(project.dir, ['three', '@types/three', '@types/node']);
    const dir = join(project.dir, 'doc-examples');
    mkdirSync(dir, { recursive: true });
    for (const doc of ['README.md', 'docs/api.md']) {
      const blocks = codeBlocks(readFileSync(join(project.dir, 'node_modules/hodt', doc), 'utf8'));
      blocks.forEach(({ lang, code }, i) => {
        if (lang !== 'ts' && lang !== 'js') return;
        const file = `${doc.replace(/\W/g, '-')}-${i}.${lang === 'ts' ? 'ts' : 'mjs'}`;
        writeFileSync(join(dir, file), code);
        written.push({ doc, file, code });
      });
    }
    const config = (moduleResolution: string) => ({
      compilerOptions: {
        strict: true,
        target: 'ES2022',
        module: moduleResolution === 'NodeNext' ? 'NodeNext' : 'ESNext',
        moduleResolution,
        lib: ['ES2022', 'DOM', 'DOM.Iterable'],
        types: ['node'],
        allowJs: true,
        checkJs: true,
        noUncheckedIndexedAccess: true,
        exactOptionalPropertyTypes: true,
        skipLibCheck: true,
        outDir: 'out',
      },
      include: ['*.ts', '*.mjs'],
    });
    writeFileSync(join(dir, 'tsconfig.json'), JSON.stringify(config('NodeNext'), null, 2));
    writeFileSync(join(dir, 'tsconfig.bundler.json'), JSON.stringify({ ...config('Bundler'), compilerOptions: { ...config('Bundler').compilerOptions, noEmit: true } }, null, 2));
  });
  const compile = (config: string) => {
    const r = spawnSync('node', [tsc, '-p', `doc-examples/${config}`], { cwd: project.dir, encoding: 'utf8' });
    expect(r.stdout + r.stderr).toBe('');
    expect(r.status).toBe(0);
  };
  const block = (doc: string, marker: string) => {
    const found = written.filter((w) => w.doc === doc && w.code.includes(marker));
    expect(found, `${doc}: one example with ${marker}`).toHaveLength(1);
    return found[0]!;
  };

  it('there are examples in both, each a complete program that imports hodt', () => {
    expect(written.filter((w) => w.doc === 'README.md').length).toBeGreaterThanOrEqual(4);
    expect(written.filter((w) => w.doc === 'docs/api.md').length).toBeGreaterThanOrEqual(8);
    for (const w of written) expect(w.code, `${w.doc}: ${w.code.slice(0, 80)}`).toMatch(/^import .* from 'hodt(\/\w+)?';$/m);
  });
  it('all compile in strict mode (NodeNext resolution), and the JavaScript ones are checked too', () => compile('tsconfig.json'));
  it('all compile in strict mode (Bundler resolution)', () => compile('tsconfig.bundler.json'));

  it('the README opens with install, import and solve, which runs as it is; the checkout\'s commands come after', () => {
    const readme = readFileSync(join(project.dir, 'node_modules/hodt/README.md'), 'utf8');
    const blocks = codeBlocks(readme);
    expect(blocks[0]).toEqual({ lang: 'sh', code: expect.stringMatching(/^npm install hodt\b/) });
    expect(blocks[1]!.lang).toBe('js');
    expect(blocks[1]!.code).toMatch(/^import \{ loadHodt \} from 'hodt';\n[\s\S]*\.solve\(/);
    expect(readme.indexOf('npm start')).toBeGreaterThan(readme.indexOf(blocks[1]!.code));
    expect(readme.indexOf('npm test')).toBeGreaterThan(readme.indexOf(blocks[1]!.code));
    const first = written.find((w) => w.doc === 'README.md' && w.code === blocks[1]!.code)!;
    const r = inProject('node', [`doc-examples/${first.file}`]);
    expect(r.stderr).toBe('');
    expect(r.stdout).toMatch(/^\d+ true Uint32Array\(\d+\)/);
  });
  it('the README Node example (plain JavaScript) runs as it is', () => {
    for (const node of ['node', ...extraNodes]) {
      const r = inProject(node, [`doc-examples/${block('README.md', "process.argv[2] ?? 'points.csv'").file}`, fixture]);
      expect(r.status, r.stderr).toBe(0);
      expect(r.stdout).toMatch(/^\d+ flippable quads; local minima: Delaunay \d+, optimal \d+\nUint32Array\(\d+\)/);
    }
  });
  it('the docs Node example (TypeScript, `using`) runs', () => {
    const r = inProject('node', [`doc-examples/out/${block('docs/api.md', "process.argv[2] ?? 'points.csv'").file.replace(/\.ts$/, '.js')}`, fixture]);
    expect(r.status, r.stderr).toBe(0);
    expect(r.stdout).toMatch(/^\d+ flippable quads; local minima: Delaunay \d+, optimal \d+\nUint32Array\(\d+\)/);
  });
  it('the hodt/export example runs and writes its files', () => {
    const r = inProject('node', [`doc-examples/out/${block('docs/api.md', "exportMesh('ply', mesh)").file.replace(/\.ts$/, '.js')}`]);
    expect(r.status, r.stderr).toBe(0);
    expect(r.stdout).toBe('3 [ 731012.3456789, 5501234.5, 12 ]\n');
    expect(readFileSync(join(project.dir, 'tin.ply'), 'latin1')).toContain('property uchar non_delaunay\n');
    expect(readFileSync(join(project.dir, 'tin.glb')).readUInt32LE(0)).toBe(0x46546c67);
  });
  it('the README accessor example runs: rows of your own, typed by their fields', () => {
    const r = inProject('node', [`doc-examples/out/${block('README.md', 'x: (r) => r.east').file.replace(/\.ts$/, '.js')}`]);
    expect(r.status, r.stderr).toBe(0);
    expect(r.stdout).toMatch(/^\d+\n$/);
  });
});

describe('browser (Vite bundle, Chromium, strict CSP)', () => {
  let dist: string;
  beforeAll(async () => {
    cpSync(join(here, 'page'), join(project.dir, 'page'), { recursive: true });
    cpSync(join(repo, 'tests/js/randomPoints.ts'), join(project.dir, 'page/randomPoints.ts'));
    cpSync(join(here, 'examples'), join(project.dir, 'examples'), { recursive: true });
    linkFromRepo(project.dir, ['three']);
    dist = join(project.dir, 'page-dist');
    const root = join(project.dir, 'page');
    await build({
      root,
      configFile: false,
      logLevel: 'warn',
      base: './', // relative URLs: the same build is served under any path
      build: {
        outDir: dist,
        emptyOutDir: true,
        chunkSizeWarningLimit: 2000,
        rollupOptions: { input: { main: join(root, 'index.html'), example: join(root, 'example.html') } },
      },
    });
    browser = await launch();
  }, 180_000);

  it('the bundle holds one hodt.wasm, and no eval', () => {
    const files = execFileSync('find', [dist, '-type', 'f'], { encoding: 'utf8' }).trim().split('\n');
    expect(files.filter((f) => f.endsWith('.wasm'))).toHaveLength(1);
    for (const f of files.filter((f) => f.endsWith('.js'))) expect(readFileSync(f, 'utf8'), f).not.toMatch(/new Function\s*\(|\beval\s*\(/);
  });

  it("solves on the page and in a module worker with script-src 'self' 'wasm-unsafe-eval'", async () => {
    const server = await serveStatic(dist, { csp: CSP });
    try {
      const w = await watchedPage(browser!);
      await w.page.goto(server.url);
      await w.page.waitForFunction(() => (window as { __smoke?: unknown }).__smoke, null, { timeout: 60_000 });
      const smoke = await w.page.evaluate(() => (window as { __smoke?: Record<string, unknown> }).__smoke!);
      expect(smoke.error).toBeUndefined();
      expect(smoke).toMatchObject({ ok: true, optimal: true, aborted: 'AbortError', inputError: 'InputError' });
      expect(smoke.indexCount).toBe((smoke.triangles as number) * 3);
      expect(smoke.worker).toMatchObject({ kind: 'solved', value: smoke.exactValue, triangles: smoke.triangles });
      const inWorker = smoke.solveInWorker as { value: number; triangles: number; long: string };
      expect(inWorker).toMatchObject({ value: smoke.exactValue, triangles: smoke.triangles });
      expect(inWorker.long).toMatch(/^AbortError after \d+ ms$/);
      expect(Number(/(\d+) ms/.exec(inWorker.long)![1])).toBeLessThan(1000);
      expect(await w.violations()).toEqual([]);
      expect(w.errors).toEqual([]);
      expect(w.warnings.filter((m) => /wasm|WebAssembly|Content Security/i.test(m))).toEqual([]);
      await w.page.close();
    } finally {
      await server.close();
    }
  });

  it('the README three.js example renders under the same CSP', async () => {
    const server = await serveStatic(dist, { csp: CSP });
    try {
      const w = await watchedPage(browser!);
      await w.page.goto(`${server.url}example.html`);
      await w.page.waitForSelector('canvas', { timeout: 60_000 });
      expect(await w.violations()).toEqual([]);
      expect(w.errors).toEqual([]);
      await w.page.close();
    } finally {
      await server.close();
    }
  });

  it("control: without 'wasm-unsafe-eval' the same page is blocked (the header is in force)", async () => {
    const server = await serveStatic(dist, { csp: CSP_WITHOUT_WASM });
    try {
      const w = await watchedPage(browser!);
      await w.page.goto(server.url);
      await w.page.waitForFunction(() => (window as { __smoke?: unknown }).__smoke, null, { timeout: 60_000 });
      const smoke = await w.page.evaluate(() => (window as { __smoke?: Record<string, unknown> }).__smoke!);
      expect(smoke.ok).toBe(false);
      expect(String(smoke.error)).toMatch(/^HodtError: could not load hodt\.wasm/);
      expect((await w.violations()).some((v) => v.startsWith('script-src'))).toBe(true);
      await w.page.close();
    } finally {
      await server.close();
    }
  });

  it('works in the Vite dev server with no configuration', async () => {
    const server = await createServer({
      root: join(project.dir, 'page'),
      configFile: false,
      logLevel: 'warn',
      server: { host: '127.0.0.1', port: 0, hmr: false, fs: { allow: [project.dir] } },
    });
    await server.listen();
    try {
      const w = await watchedPage(browser!);
      await w.page.goto(server.resolvedUrls!.local[0]!);
      await w.page.waitForFunction(() => (window as { __smoke?: unknown }).__smoke, null, { timeout: 60_000 });
      const smoke = await w.page.evaluate(() => (window as { __smoke?: Record<string, unknown> }).__smoke!);
      expect(smoke.error).toBeUndefined();
      expect(smoke).toMatchObject({ ok: true, worker: { kind: 'solved' }, solveInWorker: { long: expect.stringMatching(/^AbortError after \d+ ms$/) } });
      expect(w.errors).toEqual([]);
      await w.page.close();
    } finally {
      await server.close();
    }
  });
});
