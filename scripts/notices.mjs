// Writes THIRD_PARTY_NOTICES: what the package contains that others wrote, under
// which licenses, with the license texts. `node scripts/notices.mjs` after
// `npm run build`; `--check` exits 1 when the file is not what it would write
// (the package test runs it).
//
// Everything listed is read from where it comes from, so that it stays true:
// - the CGAL and Boost headers the wasm was compiled from: the wasm build's
//   dependency list (ninja -t deps), each CGAL header's package ($URL line) and
//   SPDX-License-Identifier;
// - the license texts: Debian's copyright files and common-licenses, and the
//   files the Emscripten package ships;
// - the npm packages: `dependencies` of package.json resolved through
//   node_modules as Node resolves them, and the packages the demo bundle
//   (dist/demo) is built from, each with its own LICENSE file.
// The Emscripten runtime libraries are the ones em++ links for this build
// (`EMCC_DEBUG=1 em++ ...` shows them on the wasm-ld line): libc (musl and
// Emscripten's own parts), libc++, libc++abi, libunwind, compiler-rt, dlmalloc,
// embind; the JavaScript glue is Emscripten's.
import { execFileSync } from 'node:child_process';
import { existsSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));
const out = join(root, 'THIRD_PARTY_NOTICES');
const read = (f) => readFileSync(f, 'utf8');

// ---- The headers in the wasm ------------------------------------------------

function wasmHeaders() {
  const build = join(root, 'build/wasm');
  if (!existsSync(join(build, 'build.ninja'))) throw new Error('notices: build/wasm missing: run `npm run build` first');
  const deps = execFileSync('ninja', ['-C', build, '-t', 'deps'], { encoding: 'utf8', maxBuffer: 1 << 28 });
  const headers = new Set();
  for (const m of deps.matchAll(/\S*?\/((?:CGAL|boost|fast_float)\/\S+)/g)) headers.add(m[1]);
  return [...headers].sort();
}

// CGAL packages (the folder of the CGAL repository a header comes from) and the
// licenses their headers carry.
function cgalPackages(headers) {
  const packages = new Map();
  for (const h of headers.filter((h) => h.startsWith('CGAL/'))) {
    const text = read(join('/usr/include', h));
    const pkg = /\$URL: \S+?\/blob\/[^/]+\/([^/]+)\//.exec(text)?.[1] ?? '(no package named)';
    const spdx = /SPDX-License-Identifier:\s*(.+)/.exec(text)?.[1]?.trim() ?? '(no SPDX line)';
    const entry = packages.get(pkg) ?? { headers: 0, licenses: new Set() };
    entry.headers += 1;
    entry.licenses.add(spdx);
    packages.set(pkg, entry);
  }
  return [...packages].sort(([a], [b]) => a.localeCompare(b));
}

function boostLibraries(headers) {
  const libs = new Set(headers.filter((h) => h.startsWith('boost/')).map((h) => h.split('/')[1].replace(/\.(h|hpp)$/, '')));
  return [...libs].sort();
}

// ---- License texts ----------------------------------------------------------

// A stand-alone "License: NAME" paragraph of a Debian copyright file, as text.
function debianLicense(file, name) {
  const lines = read(file).split('\n');
  const at = lines.findIndex((l, i) => /^License:\s+(.*?)\s*$/.exec(l)?.[1] === name && (i === 0 || lines[i - 1].trim() === ''));
  if (at < 0) throw new Error(`notices: no "License: ${name}" paragraph in ${file}`);
  const body = [];
  for (const l of lines.slice(at + 1)) {
    if (!l.startsWith(' ')) break;
    body.push(l === ' .' ? '' : l.slice(1));
  }
  return body.join('\n');
}
const commonLicense = (name) => read(join('/usr/share/common-licenses', name)).trimEnd();
const emscripten = '/usr/share/emscripten';
const version = (file, pattern) => pattern.exec(read(file))?.[1] ?? '?';

// The LLVM exception, as Debian's emscripten copyright quotes it for libc++.
function llvmException() {
  const text = read('/usr/share/doc/emscripten/copyright');
  const m = /License: Apache-2\.0 with LLVM exception\n((?: .*\n)+)/.exec(text);
  if (!m) throw new Error('notices: no LLVM exception in the emscripten copyright file');
  return m[1].split('\n').map((l) => (l === ' .' ? '' : l.slice(1))).join('\n').trimEnd();
}

// ---- npm packages -----------------------------------------------------------

// Where Node finds package `name` from the folder `from` (a package's folder).
function resolvePackage(name, from) {
  for (let dir = from; ; dir = dirname(dir)) {
    const candidate = join(dir, 'node_modules', name, 'package.json');
    if (existsSync(candidate)) return dirname(candidate);
    if (dir === root || dirname(dir) === dir) return null;
  }
}

// Every package reached from `names` through `dependencies` (and the optional
// ones installed), each once: [{ name, version, license, repository, dir }].
function dependencyTree(names, from, { recursive = true } = {}) {
  const found = new Map();
  const visit = (name, dir, optional) => {
    const at = resolvePackage(name, dir);
    if (!at) {
      if (optional) return;
      throw new Error(`notices: ${name} (needed from ${dir}) is not installed: run npm install`);
    }
    const pkg = JSON.parse(read(join(at, 'package.json')));
    const key = `${pkg.name}@${pkg.version}`;
    if (found.has(key)) return;
    const repository = typeof pkg.repository === 'string' ? pkg.repository : pkg.repository?.url ?? '';
    const license = typeof pkg.license === 'string' ? pkg.license : pkg.license?.type ?? '(none given)';
    found.set(key, { name: pkg.name, version: pkg.version, license, repository, dir: at });
    if (!recursive) return;
    for (const dep of Object.keys(pkg.dependencies ?? {})) visit(dep, at, false);
    for (const dep of Object.keys(pkg.optionalDependencies ?? {})) visit(dep, at, true);
  };
  for (const name of names) visit(name, from, false);
  return [...found.values()].sort((a, b) => a.name.localeCompare(b.name) || a.version.localeCompare(b.version));
}

function licenseFiles(dir) {
  return readdirSync(dir)
    .filter((f) => /^(licen[cs]e|copying|notice)/i.test(f))
    .sort()
    .map((f) => ({ file: f, text: read(join(dir, f)).trimEnd() }));
}

// The packages the demo's source imports by name: the bundle holds their code
// (or data), not their dependencies' (vega-datasets': only its data is imported).
function demoImports() {
  const names = new Set();
  const visit = (dir) => {
    for (const entry of readdirSync(dir, { withFileTypes: true })) {
      const path = join(dir, entry.name);
      if (entry.isDirectory()) visit(path);
      else if (/\.(ts|js)$/.test(entry.name)) {
        for (const m of read(path).matchAll(/^import\s[^'"]*['"]([^./'"][^'"]*)['"]/gm)) {
          const spec = m[1];
          const name = spec.startsWith('@') ? spec.split('/').slice(0, 2).join('/') : spec.split('/')[0];
          if (name !== 'hodt') names.add(name);
        }
      }
    }
  };
  visit(join(root, 'web/demo/src'));
  // The demo's Vite config maps the alias vega-data to vega-datasets' data folder.
  const aliases = { 'vega-data': 'vega-datasets' };
  return [...names].map((n) => aliases[n] ?? n).sort();
}

// ---- The file ---------------------------------------------------------------

const rule = (title) => `\n${'='.repeat(78)}\n${title}\n${'='.repeat(78)}\n`;
const sub = (title) => `\n${'-'.repeat(78)}\n${title}\n${'-'.repeat(78)}\n`;

// License texts this file already gives in full, for packages without a file.
const TEXT_ABOVE = { 'Apache-2.0': 'in the LLVM section above', MIT: "in Emscripten's section above", 'BSL-1.0': "in Boost's section above" };

function npmSection(packages) {
  return packages
    .map((p) => {
      const files = licenseFiles(p.dir);
      const head = `npm package: ${p.name}@${p.version}\nLicense: ${p.license}\n${p.repository ? `Repository: ${p.repository}\n` : ''}`;
      const body = files.length
        ? files.map((f) => `\n${f.file}:\n\n${f.text}\n`).join('')
        : `\n(The package ships no license file; its package.json says ${p.license}${TEXT_ABOVE[p.license] ? `, whose text is ${TEXT_ABOVE[p.license]}` : ''}.)\n`;
      return sub(`${p.name} ${p.version}`) + head + body;
    })
    .join('');
}

// The SPDX expression of what the package contains: hodt's MIT, the licenses of
// the code compiled into the wasm (CGAL's under the LGPL, not the commercial
// alternative; Emscripten's under MIT, not NCSA), and those of the packages
// bundled in the demo. The installed dependencies are packages of their own,
// with their own "license" fields.
export function packageLicense() {
  const headers = wasmHeaders();
  const cgal = cgalPackages(headers).flatMap(([, e]) => [...e.licenses].map((l) => l.replace(/ OR LicenseRef-Commercial$/, '')));
  const demo = dependencyTree(demoImports(), root, { recursive: false }).map((p) => p.license);
  const ids = new Set(['MIT', ...cgal, 'BSL-1.0', 'Apache-2.0 WITH LLVM-exception', 'CC0-1.0', ...demo]);
  return [...ids].join(' AND ');
}

export function notices() {
  const pkg = JSON.parse(read(join(root, 'package.json')));
  const headers = wasmHeaders();
  const cgal = cgalPackages(headers);
  const boost = boostLibraries(headers);
  const fastFloat = headers.some((h) => h.startsWith('fast_float/'));
  const cgalVersion = version('/usr/include/CGAL/version.h', /#define CGAL_VERSION (\S+)/);
  const boostVersion = version('/usr/include/boost/version.hpp', /#define BOOST_LIB_VERSION "(\S+)"/).replace('_', '.');
  const emVersion = read(join(emscripten, 'emscripten-version.txt')).trim().replace(/"/g, '');
  const installed = dependencyTree(Object.keys(pkg.dependencies ?? {}), root);
  const demo = dependencyTree(demoImports(), root, { recursive: false });
  const cgalLicenses = [...new Set(cgal.flatMap(([, e]) => [...e.licenses]))].sort();

  const wasmParts = [
    `hodt's C++ core (MIT) compiled with Emscripten ${emVersion}, together with the parts of CGAL ${cgalVersion} it uses (${cgalLicenses.join('; ')}),`,
    `Boost ${boostVersion} headers (BSL-1.0),`,
    ...(fastFloat ? ['fast_float (MIT OR Apache-2.0),'] : []),
    "and Emscripten's runtime libraries (musl: MIT; libc++, libc++abi, libunwind, compiler-rt: Apache-2.0 WITH LLVM-exception; dlmalloc: CC0-1.0; Emscripten's own code: MIT OR NCSA).",
  ];
  let s = `Third-party software in the hodt package ${pkg.version}

${wrap(`hodt itself is under the MIT license (LICENSE). The package also contains, or installs, software that others wrote, under the licenses below; package.json's "license", ${packageLicense()}, names every license of what the package contains.`, '')}

${wrap(`- dist/wasm/hodt.wasm (and its copy in dist/demo/assets/): ${wasmParts.join(' ')}`, '', '  ')}
- dist/wasm/hodt.mjs: Emscripten's JavaScript glue (MIT OR NCSA).
${wrap(`- dist/demo/: the teaching demo, bundled with code or data of the npm packages it imports: ${demo.map((p) => `${p.name} (${p.license})`).join(', ')}; listed at the end.`, '', '  ')}
${wrap(`- Installed beside hodt (package.json "dependencies", for hodt/loaders and the CLI), not contained in it: ${installed.map((p) => `${p.name}@${p.version}`).join(', ')}; listed below with their licenses.`, '', '  ')}

This file is written by scripts/notices.mjs from the wasm build's headers,
Debian's copyright files and node_modules.
`;

  s += rule('CGAL: GNU Lesser General Public License, version 3 or later');
  s += `
hodt.wasm contains code compiled from these packages of CGAL ${cgalVersion}
(https://www.cgal.org, the Debian package libcgal-dev), the exact predicates and
number types: the kernel and what it needs (header counts; each header's own
SPDX-License-Identifier):

${cgal.map(([name, e]) => `  ${name.padEnd(24)} ${String(e.headers).padStart(4)} headers  ${[...e.licenses].join('; ')}`).join('\n')}

These CGAL parts are licensed under the GNU Lesser General Public License,
version 3 or (at your option) any later version ("LGPL-3.0-or-later OR
LicenseRef-Commercial": GeometryFactory also sells commercial licenses). hodt
uses them under the LGPL. CGAL's own words (from its LICENSE file, as Debian
quotes it):

   This file is part of CGAL (www.cgal.org); you can redistribute it and/or
   modify it under the terms of the GNU Lesser General Public License as
   published by the Free Software Foundation; either version 3 of the License,
   or (at your option) any later version.

   This file is provided AS IS with NO WARRANTY OF ANY KIND, INCLUDING THE
   WARRANTY OF DESIGN, MERCHANTABILITY AND FITNESS FOR A PARTICULAR PURPOSE.

Copyright holders of CGAL include Utrecht University (The Netherlands), ETH
Zurich (Switzerland), Freie Universitaet Berlin (Germany), INRIA
Sophia-Antipolis (France), Martin-Luther-University Halle-Wittenberg (Germany),
Max-Planck-Institute Saarbruecken (Germany), RISC Linz (Austria), Tel-Aviv
University (Israel), Stanford University (USA), Foundation for Research and
Technology-Hellas (Greece), GeometryFactory; each header names its own.

Relinking (LGPL-3.0 section 4). hodt.wasm is one statically linked
WebAssembly module: hodt's code and CGAL's are combined in it. What the LGPL
asks of such a Combined Work is met as follows:
- The complete source of hodt (the "Corresponding Application Code") is
  public, under the MIT license: https://github.com/hodt-project/hodt
  (version ${pkg.version} of its package.json). CGAL's source is the Debian
  package libcgal-dev ${cgalVersion}, or https://github.com/CGAL/cgal.
- To use a modified CGAL (or any other version), rebuild hodt.wasm from that
  source on Debian 12: \`npm run build\` installs the toolchain (emscripten,
  libcgal-dev, libboost-dev) with scripts/setup.mjs and writes
  build/wasm/hodt.wasm and its glue build/wasm/hodt.mjs; point the build at
  your CGAL by replacing the build/wasm/sysinc/CGAL link (or CGAL in
  /usr/include) with your copy's include/CGAL. The two files replace
  dist/wasm/hodt.wasm and dist/wasm/hodt.mjs in the installed package
  (node_modules/hodt/dist/wasm/). When the rebuilt hodt.mjs is the same as the
  shipped one (the same Emscripten and settings give the same glue unless the
  wasm's imports change), the rebuilt wasm alone will do, given to
  loadHodt({ wasmUrl }) or loadHodt({ wasmBinary }) without touching the
  package: the JavaScript API reaches the wasm only through its exported
  interface (wasm/bindings.cpp). The same build writes the demo with the
  rebuilt wasm (build/demo, which the package ships as dist/demo).
- Nothing in the package restricts modification of CGAL or reverse
  engineering for debugging such modifications.
The texts of the GNU LGPL version 3 and of the GNU GPL version 3, which it
supplements, follow.
`;
  s += sub('GNU Lesser General Public License, version 3') + '\n' + commonLicense('LGPL-3') + '\n';
  s += sub('GNU General Public License, version 3') + '\n' + commonLicense('GPL-3') + '\n';

  s += rule(`Boost ${boostVersion}: Boost Software License 1.0`);
  s += `
hodt.wasm contains code from these Boost header libraries (Boost.Multiprecision
is CGAL's exact fallback without GMP; the others come in through CGAL):
${wrap(boost.join(', '), '  ')}

Copyright: Boost project contributors (each header names its authors).

${debianLicense(`/usr/share/doc/libboost${boostVersion}-dev/copyright`, 'BSL-1.0')}
`;

  if (fastFloat) {
    s += rule('fast_float: MIT or Apache-2.0');
    s += `
hodt.wasm contains fast_float (https://github.com/fastfloat/fast_float, the
Debian package libfast-float-dev), used to read numbers correctly rounded.
Copyright Daniel Lemire and the fast_float contributors. Under the MIT license
or the Apache License 2.0, at your option; hodt uses it under the MIT license:

${debianLicense('/usr/share/doc/libfast-float-dev/copyright', 'Expat')}
`;
  }

  s += rule(`Emscripten ${emVersion} runtime`);
  s += `
em++ links these libraries of Emscripten (https://emscripten.org, the Debian
package emscripten) into hodt.wasm, and writes hodt.mjs, its JavaScript glue.
`;
  s += sub("Emscripten's own code (embind, its libc parts, the JavaScript glue): MIT OR NCSA");
  s += `
Copyright (c) 2010-2022 The Emscripten Authors. Emscripten is available under
two separate licenses, the MIT license and the University of Illinois/NCSA Open
Source License; hodt uses it under the MIT license:

${debianLicense('/usr/share/doc/emscripten/copyright', 'Expat')}
`;
  s += sub('musl libc: MIT');
  s += '\n' + read(join(emscripten, 'system/lib/libc/musl/COPYRIGHT')).trimEnd() + '\n';
  s += sub('libc++, libc++abi, libunwind, compiler-rt (LLVM): Apache-2.0 WITH LLVM-exception');
  s += `
Part of the LLVM Project, under the Apache License v2.0 with LLVM Exceptions
(https://llvm.org/LICENSE.txt). Copyright: the LLVM contributors (see
CREDITS.TXT of each library in Emscripten's system/lib).

LLVM Exceptions to the Apache 2.0 License:

${llvmException()}

${commonLicense('Apache-2.0')}
`;
  s += sub('dlmalloc (the allocator): public domain, CC0-1.0');
  s += `
This is a version (aka dlmalloc) of malloc/free/realloc written by Doug Lea and
released to the public domain, as explained at
http://creativecommons.org/publicdomain/zero/1.0/
`;

  s += rule('npm packages installed with hodt (package.json "dependencies")');
  s += `
npm installs these beside hodt: ${installed.length} packages, the whole
dependency tree of ${Object.keys(pkg.dependencies ?? {}).join(' and ')}. Each with its license file.
`;
  s += npmSection(installed);

  s += rule('npm packages bundled in the demo (dist/demo)');
  s += `
The demo served by \`npx hodt demo\` is a Vite build that contains code (or, for
vega-datasets, the volcano elevation data) of these packages:
`;
  s += npmSection(demo);
  return s;
}

// Words joined into lines of at most 78 characters: the first line starts with
// `first`, the others with `rest`.
function wrap(text, first, rest = first) {
  const lines = [];
  let line = first;
  for (const word of text.split(' ')) {
    if (line.length + word.length > 78 && line.trim()) lines.push(line.trimEnd()), (line = rest);
    line += word + ' ';
  }
  lines.push(line.trimEnd());
  return lines.join('\n');
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const text = notices();
  const license = packageLicense();
  const pkgFile = join(root, 'package.json');
  const pkg = JSON.parse(read(pkgFile));
  if (process.argv.includes('--check')) {
    const current = existsSync(out) ? read(out) : '';
    const stale = [
      ...(current !== text ? ['THIRD_PARTY_NOTICES is out of date'] : []),
      ...(pkg.license !== license ? [`package.json's license is '${pkg.license}', expected '${license}'`] : []),
    ];
    if (stale.length) {
      console.error(`${stale.join('; ')}: run \`node scripts/notices.mjs\``);
      process.exit(1);
    }
  } else {
    writeFileSync(out, text);
    if (pkg.license !== license) writeFileSync(pkgFile, read(pkgFile).replace(/"license": "[^"]*"/, `"license": ${JSON.stringify(license)}`));
  }
}
