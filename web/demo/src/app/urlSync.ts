import { encodeState, MAX_HASH_CHARS, type SharedState } from '../share/urlState.ts';

/** Keeps the URL hash in step with the page state (debounced, without adding
 * browser history entries), so that reloading or copying the address bar keeps
 * the state. Returns the function to call after every change. */
export function createUrlSync(read: () => SharedState, delayMs = 250): { changed(): void; link(): string | null } {
  let timer = 0;
  let lastHash = '';
  const link = () => {
    const hash = encodeState(read());
    if (hash.length > MAX_HASH_CHARS) return null;
    return `${location.origin}${location.pathname}${location.search}${hash}`;
  };
  const write = () => {
    timer = 0;
    const hash = encodeState(read());
    if (hash.length > MAX_HASH_CHARS || hash === lastHash) return;
    lastHash = hash;
    history.replaceState(null, '', hash);
  };
  return {
    changed() {
      clearTimeout(timer);
      timer = window.setTimeout(write, delayMs);
    },
    link,
  };
}
