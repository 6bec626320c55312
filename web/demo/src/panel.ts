import type { ObjectiveId, ObjectiveInfo } from 'hodt';
import { hypsometricGradient } from './colormap.ts';
import { FLIPPED_COLOR, QUAD_COLOR } from './quads.ts';

export type StatusKind = 'info' | 'busy' | 'ok' | 'error';

/** The header card: counts, objective picker, Optimize button and status line. */
export interface Panel {
  setCounts(counts: { points: number; triangles: number; quads: number }): void;
  setObjectives(list: readonly ObjectiveInfo[]): void;
  onOptimize(handler: (id: ObjectiveId) => void): void;
  setBusy(busy: boolean): void;
  setStatus(text: string, kind?: StatusKind): void;
}

function byId<T extends HTMLElement>(id: string): T {
  const el = document.getElementById(id);
  if (!el) throw new Error(`missing #${id} in index.html`);
  return el as T;
}

export function bindPanel(): Panel {
  const select = byId<HTMLSelectElement>('objective');
  const summary = byId<HTMLElement>('objective-summary');
  const button = byId<HTMLButtonElement>('optimize');
  const status = byId<HTMLElement>('status');
  let objectives: readonly ObjectiveInfo[] = [];

  byId('legend-elevation').style.background = hypsometricGradient();
  byId('legend-quad').style.background = QUAD_COLOR;
  byId('legend-flipped').style.background = FLIPPED_COLOR;

  const showSummary = () => {
    const info = objectives.find((o) => o.id === select.value);
    summary.textContent = info ? `${info.sense === 'min' ? 'Minimise' : 'Maximise'}: ${info.summary}` : '';
    select.title = info?.summary ?? '';
  };
  select.addEventListener('change', showSummary);

  return {
    setCounts({ points, triangles, quads }) {
      byId('count-points').textContent = points.toLocaleString('en');
      byId('count-triangles').textContent = triangles.toLocaleString('en');
      byId('count-quads').textContent = quads.toLocaleString('en');
      byId('count-m').textContent = String(quads);
    },
    setObjectives(list) {
      objectives = list;
      select.replaceChildren(
        ...list.map((o) => {
          const option = document.createElement('option');
          option.value = o.id;
          option.textContent = o.id;
          option.title = o.summary;
          return option;
        }),
      );
      select.disabled = false;
      button.disabled = false;
      showSummary();
    },
    onOptimize(handler) {
      button.addEventListener('click', () => handler(select.value as ObjectiveId));
    },
    setBusy(busy) {
      button.disabled = busy;
      select.disabled = busy;
    },
    setStatus(text, kind = 'info') {
      status.textContent = text;
      status.dataset.kind = kind;
    },
  };
}
