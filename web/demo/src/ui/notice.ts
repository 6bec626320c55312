import { byId } from './dom.ts';

/** One message over the views: errors (bad file, bad link, refused edit) and
 * notes. Stays until dismissed or replaced. */
export interface Notice {
  show(text: string, kind?: 'error' | 'info'): void;
  hide(): void;
}

export function createNotice(): Notice {
  const root = byId('notice');
  const text = byId('notice-text');
  let timer = 0;
  const hide = () => {
    root.hidden = true;
    clearTimeout(timer);
  };
  byId('notice-close').addEventListener('click', hide);
  return {
    show(message, kind = 'error') {
      clearTimeout(timer);
      text.textContent = message;
      root.dataset.kind = kind;
      root.hidden = false;
      if (kind === 'info') timer = window.setTimeout(hide, 6000);
    },
    hide,
  };
}
