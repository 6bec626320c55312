// How the loaders refuse a file: an InputError whose message is one printable
// line, with anything quoted from the file escaped.
import { InputError } from '../errors.js';

/** Throws the loaders' one error: `format: what` (the CLI prefixes the file's name). */
export function fail(format: string, what: string): never {
  throw new InputError(`${format}: ${what}`);
}

/** Text from a file as a message may show it: control and non-ASCII bytes as
 * escapes, at most 40 characters, quoted. */
export function quoted(text: string): string {
  const shown = text.length > 40 ? `${text.slice(0, 40)}...` : text;
  return `'${shown.replace(/[^\x20-\x7e]|'/g, (c) => (c === "'" ? "\\'" : `\\x${c.charCodeAt(0).toString(16).padStart(2, '0').slice(-2)}`))}'`;
}

/** Any error thrown while decoding, as the loaders' one error. Errors of the
 * loaders themselves pass through; anything else (a decoder's own exception,
 * a wasm trap, a RangeError) is named as a failure of the named step. */
export function rethrow(format: string, step: string, e: unknown): never {
  if (e instanceof InputError) throw e;
  const detail = e === undefined ? '' : e instanceof Error ? e.message : String(e);
  // (a decoder's message is its own text: one line, printable, short)
  const line = detail.split(/\r?\n/)[0]!.replace(/[^\x20-\x7e]/g, '?').slice(0, 120);
  throw new InputError(`${format}: ${step}${line ? ` (${line})` : ''}`, { cause: e });
}
