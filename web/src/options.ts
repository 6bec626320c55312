import { describeValue, InputError } from './errors.js';

/**
 * Throws InputError for an options argument that is not an object, or that has a
 * key this call does not know (a misspelt option would otherwise be ignored in
 * silence): "unknown solve option 'metod' (did you mean 'method'?)".
 */
export function checkOptionNames(what: string, options: unknown, known: readonly string[]): void {
  if (options === undefined || options === null) return;
  if (typeof options !== 'object' || Array.isArray(options))
    throw new InputError(`${what} options are ${describeValue(options)}, expected an object`);
  for (const key of Object.keys(options)) {
    if (known.includes(key)) continue;
    const near = closest(key, known);
    throw new InputError(
      `unknown ${what} option '${key}'` +
        (near ? ` (did you mean '${near}'?)` : ` (expected ${known.map((k) => `'${k}'`).join(', ')})`),
    );
  }
}

// The known name within two edits of `key`, if one is.
function closest(key: string, known: readonly string[]): string | undefined {
  let best: string | undefined;
  let bestDistance = 3;
  for (const k of known) {
    const d = editDistance(key.toLowerCase(), k.toLowerCase());
    if (d < bestDistance) best = k, bestDistance = d;
  }
  return best;
}

function editDistance(a: string, b: string): number {
  let row = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; ++i) {
    const next = [i];
    for (let j = 1; j <= b.length; ++j)
      next[j] = Math.min(row[j]! + 1, next[j - 1]! + 1, row[j - 1]! + (a[i - 1] === b[j - 1] ? 0 : 1));
    row = next;
  }
  return row[b.length]!;
}
