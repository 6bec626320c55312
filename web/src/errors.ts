// Names are spelled out: minifiers rename classes, so `new.target.name` would not do.

/** Base class of every error hodt throws; `message` is the core's own text. */
export class HodtError extends Error {
  override name = 'HodtError';
  constructor(message: string, options?: { cause?: unknown }) {
    super(message, options);
  }
}
/** Bad input: malformed file, NaN coordinate, duplicate point, invalid choice or
 * option (an unknown objective or method, an order outside 1 to 16). */
export class InputError extends HodtError {
  override name = 'InputError';
}
/** A call on a terrain made from inside the progress callback of its own solve():
 * the core is still using the terrain, so changing or freeing it then (dispose,
 * addPoint, movePoint, removePoint) or starting another solve is refused. */
export class BusyError extends InputError {
  override name = 'BusyError';
}
/** A valid request the library refuses: too many quads for brute force, a tree
 * decomposition wider than the memory cap, out of memory. */
export class LimitError extends HodtError {
  override name = 'LimitError';
}
/**
 * The run was cancelled: its AbortSignal was aborted (`cause` is the signal's
 * reason) or the progress callback returned false. Its `name` is 'AbortError', as
 * for an aborted fetch(), so code that checks `e.name === 'AbortError'` works too.
 */
export class CancelledError extends HodtError {
  override name = 'AbortError';
  constructor(message = 'cancelled', options?: { cause?: unknown }) {
    super(message, options);
  }
}
/** A bug in hodt: please report it with the input. */
export class InternalError extends HodtError {
  override name = 'InternalError';
}

/** A value as a message shows it: strings quoted, BigInts with their n. */
export function describeValue(value: unknown): string {
  if (typeof value === 'string') return `'${value}'`;
  if (typeof value === 'bigint') return `${value}n`;
  if (typeof value === 'symbol') return value.toString();
  try {
    return String(value);
  } catch {
    return Object.prototype.toString.call(value);  // an object without a usable toString
  }
}

/** Turns an error thrown by the wasm module into the matching typed error. */
export function toHodtError(e: unknown): unknown {
  if (!(e instanceof Error) || e instanceof HodtError) return e;
  switch (e.name) {
    case 'InputError':
      return new InputError(e.message);
    case 'LimitError':
      return new LimitError(e.message);
    case 'Cancelled':
      return new CancelledError(e.message);
    case 'InternalError':
      return new InternalError(e.message);
    default:
      return e;
  }
}

/** Calls f, rethrowing wasm errors as typed errors. */
export function guard<T>(f: () => T): T {
  try {
    return f();
  } catch (e) {
    throw toHodtError(e);
  }
}
