import './style.css';
import { loadHodt } from 'hodt';
import { startApp } from './app/app.ts';
import { byId } from './ui/dom.ts';

/** Remembers whether the intro was folded away. */
function rememberIntro(): void {
  const intro = byId<HTMLDetailsElement>('intro');
  const key = 'hodt-demo-intro-closed';
  try {
    if (localStorage.getItem(key) === '1') intro.open = false;
    intro.addEventListener('toggle', () => localStorage.setItem(key, intro.open ? '0' : '1'));
  } catch {
    // storage disabled: the intro simply starts open
  }
}

async function main(): Promise<void> {
  rememberIntro();
  const result = byId('result');
  result.textContent = 'Loading the WebAssembly module…';
  startApp(await loadHodt());
}

main().catch((e: unknown) => {
  // Never a blank page: say what went wrong where the result would be.
  const text = `The demo could not start: ${e instanceof Error ? e.message : String(e)}`;
  const notice = document.getElementById('notice');
  const noticeText = document.getElementById('notice-text');
  if (notice && noticeText) {
    noticeText.textContent = text;
    notice.hidden = false;
    notice.dataset.kind = 'error';
  }
  console.error(e);
});
