// Parts of the docs that a script writes from what it measures, each between
// `<!-- NAME: written by WRITER -->` and `<!-- /NAME -->`, so that the numbers in
// the docs are the script's output and a check can tell when they are stale.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

/**
 * The docs with their blocks replaced: `generated` maps a file (relative to
 * `repo`) to its blocks' names and bodies (a body without a line end stays on
 * the markers' line). Returns the files whose text differs; `write` writes them.
 * @param {string} repo
 * @param {string} writer the script's path, as the markers name it
 * @param {Record<string, Record<string, string>>} generated
 * @param {{ write: boolean }} options
 * @returns {string[]}
 */
export function updateBlocks(repo, writer, generated, { write }) {
  const stale = [];
  const escaped = writer.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  for (const [file, blocks] of Object.entries(generated)) {
    const path = join(repo, file);
    const text = readFileSync(path, 'utf8');
    let next = text;
    for (const [name, body] of Object.entries(blocks)) {
      const re = new RegExp(`(<!-- ${name}: written by ${escaped} -->)[\\s\\S]*?(<!-- /${name} -->)`);
      if (!re.test(next)) throw new Error(`${file}: no <!-- ${name}: written by ${writer} --> ... <!-- /${name} --> markers`);
      const inline = !/\n/.test(body);
      next = next.replace(re, (_, open, close) => (inline ? `${open}${body}${close}` : `${open}\n${body}\n${close}`));
    }
    if (next !== text) {
      stale.push(file);
      if (write) writeFileSync(path, next);
    }
  }
  return stale;
}
