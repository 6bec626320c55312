// The core's layout as core/README.md declares it: every folder of core/src is
// in its table, and every include names a public header (hodt/...), a header of
// its own folder, or one of a folder the table lets it include, and the table
// has no cycle among its folders. The public
// headers include only each other, so the front ends need no private path.
import { readFileSync, readdirSync } from 'node:fs';
import { join, relative, dirname } from 'node:path';
import { describe, expect, it } from 'vitest';

const root = join(__dirname, '../..');
const src = join(root, 'core/src');
const publicDir = join(root, 'core/include/hodt');

function filesUnder(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? filesUnder(join(dir, e.name)) : [join(dir, e.name)],
  );
}

/** folder -> folders it may include, from core/README.md's table. */
function declared(): Map<string, Set<string>> {
  const table = new Map<string, Set<string>>();
  for (const line of readFileSync(join(root, 'core/README.md'), 'utf8').split('\n')) {
    const m = /^\| `([a-z_/]+)` \|[^|]*\|([^|]*)\|$/.exec(line);
    if (m) table.set(m[1], new Set([...m[2].matchAll(/`([a-z_/]+)`/g)].map((x) => x[1])));
  }
  return table;
}

const includes = (file: string) =>
  [...readFileSync(file, 'utf8').matchAll(/^#include "([^"]+)"/gm)].map((m) => m[1]);

describe('core layout', () => {
  const table = declared();

  it('the table lists every folder of core/src, and only those', () => {
    const folders = new Set(filesUnder(src).map((f) => relative(src, dirname(f))));
    expect([...table.keys()].sort()).toEqual([...folders].sort());
  });

  it('every include of core/src is allowed by the table', () => {
    const wrong: string[] = [];
    for (const file of filesUnder(src)) {
      const own = relative(src, dirname(file));
      for (const inc of includes(file)) {
        const folder = dirname(inc);
        if (folder === 'hodt' || folder === own || table.get(own)?.has(folder)) continue;
        wrong.push(`${relative(root, file)} includes ${inc}`);
      }
    }
    expect(wrong).toEqual([]);
  });

  it('the folders the table lets each include form no cycle: each folder builds on those below it', () => {
    const cycles: string[] = [];
    const state = new Map<string, 'open' | 'done'>();
    const visit = (folder: string, path: string[]) => {
      if (state.get(folder) === 'done') return;
      if (state.get(folder) === 'open') {
        cycles.push([...path.slice(path.indexOf(folder)), folder].join(' -> '));
        return;
      }
      state.set(folder, 'open');
      for (const next of table.get(folder) ?? []) visit(next, [...path, folder]);
      state.set(folder, 'done');
    };
    for (const folder of table.keys()) visit(folder, []);
    expect(cycles).toEqual([]);
  });

  it('the public headers include only public headers', () => {
    const wrong = filesUnder(publicDir).flatMap((file) =>
      includes(file)
        .filter((inc) => !inc.startsWith('hodt/'))
        .map((inc) => `${relative(root, file)} includes ${inc}`),
    );
    expect(wrong).toEqual([]);
  });

  it('the front ends include only public headers', () => {
    const fronts = ['wasm', 'core/cli', 'bench'].flatMap((d) =>
      filesUnder(join(root, d)).filter((f) => /\.(cpp|hpp)$/.test(f)),
    );
    const wrong = fronts.flatMap((file) =>
      includes(file)
        .filter((inc) => inc.includes('/') && !inc.startsWith('hodt/'))
        .map((inc) => `${relative(root, file)} includes ${inc}`),
    );
    expect(wrong).toEqual([]);
  });
});
