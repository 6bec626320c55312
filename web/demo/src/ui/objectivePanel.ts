import type { Method, ObjectiveId, ObjectiveInfo } from 'hodt';
import { METHODS } from '../app/settings.ts';
import { byId, h } from './dom.ts';
import { orderOptions } from './orderOptions.ts';
import { OBJECTIVE_HELP } from './objectiveHelp.ts';

export interface SolveSettings {
  objective: ObjectiveId;
  method: Method;
  epsilon: number;
  /** Order k: 1 for first order; k >= 2 searches the order-k Delaunay
   * triangulations (the library picks its method). */
  order: number;
  /** The domain (Terrain.maxEdge): triangles with a longer edge are outside and
   * not measured; null measures every triangle. */
  maxEdge: number | null;
}

/** Objective picker with its help text, method and epsilon. */
export interface ObjectivePanel {
  set(s: SolveSettings): void;
  get(): SolveSettings;
  onChange(handler: (s: SolveSettings) => void): void;
  /** Picks an objective as if chosen in the list. */
  choose(id: ObjectiveId): void;
  /** The "useful edges" toggle. */
  onUseful(handler: (show: boolean) => void): void;
  readonly showUseful: boolean;
  /** The count line under the order row (null hides it). */
  setUsefulCount(text: string | null): void;
}

const METHOD_LABELS: Record<Method, string> = {
  auto: 'auto',
  exact: 'exact',
  approx: 'approx',
  'brute-force': 'brute force',
};
const METHOD_TITLES: Record<Method, string> = {
  auto: 'Exact when the problem decomposes well enough, else the approximation',
  exact: 'Exact algorithm; refuses instances too wide for its memory cap',
  approx: 'Approximation with a proven bound (epsilon sets the accuracy)',
  'brute-force': 'Tries all 2^m triangulations: only for m ≤ 24 quads',
};

export function createObjectivePanel(objectives: readonly ObjectiveInfo[]): ObjectivePanel {
  const select = byId<HTMLSelectElement>('objective');
  const help = byId('objective-help');
  const method = byId<HTMLSelectElement>('method');
  const epsilon = byId<HTMLInputElement>('epsilon');
  const order = byId<HTMLSelectElement>('order');
  const useful = byId<HTMLInputElement>('show-useful');
  const usefulCount = byId('useful-count');
  const maxEdge = byId<HTMLInputElement>('max-edge');
  order.replaceChildren(...orderOptions());

  select.replaceChildren(
    ...objectives.map((o) =>
      h('option', { value: o.id, title: o.summary }, OBJECTIVE_HELP[o.id].name),
    ),
  );
  method.replaceChildren(...METHODS.map((m) => h('option', { value: m, title: METHOD_TITLES[m] }, METHOD_LABELS[m])));

  /** Epsilon only matters to the approximation (which auto may fall back to). */
  const enableEpsilon = () => {
    const higher = Number(order.value) > 1;
    // Order k >= 2 chooses its method itself (exact enumeration or k-OD flips).
    method.disabled = higher;
    method.title = higher ? `Order ${order.value} chooses its method itself` : '';
    epsilon.disabled = higher || (method.value !== 'approx' && method.value !== 'auto');
  };
  const get = (): SolveSettings => ({
    objective: select.value as ObjectiveId,
    method: method.value as Method,
    epsilon: clampEpsilon(Number(epsilon.value)),
    order: Number(order.value) || 1,
    maxEdge: readMaxEdge(maxEdge.value),
  });
  const showHelp = () => {
    const id = select.value as ObjectiveId;
    const info = objectives.find((o) => o.id === id);
    const text = OBJECTIVE_HELP[id];
    help.replaceChildren(
      h('b', {}, info?.sense === 'max' ? 'Maximise. ' : 'Minimise. '),
      text.help,
      text.hard ? h('span', { class: 'tag' }, 'NP-hard') : '',
      h('code', { class: 'id' }, id),
    );
  };
  const listeners: ((s: SolveSettings) => void)[] = [];
  const changed = () => {
    showHelp();
    enableEpsilon();
    const s = get();
    epsilon.value = String(s.epsilon);
    maxEdge.value = s.maxEdge === null ? '' : String(s.maxEdge);
    for (const l of listeners) l(s);
  };
  select.addEventListener('change', changed);
  method.addEventListener('change', changed);
  epsilon.addEventListener('change', changed);
  order.addEventListener('change', changed);
  maxEdge.addEventListener('change', changed);
  const usefulListeners: ((show: boolean) => void)[] = [];
  useful.addEventListener('change', () => usefulListeners.forEach((l) => l(useful.checked)));

  return {
    set(s) {
      select.value = s.objective;
      method.value = s.method;
      epsilon.value = String(s.epsilon);
      order.value = String(s.order);
      maxEdge.value = s.maxEdge === null ? '' : String(s.maxEdge);
      showHelp();
      enableEpsilon();
    },
    get,
    onChange(handler) {
      listeners.push(handler);
    },
    choose(id) {
      if (select.value === id) return;
      select.value = id;
      changed();
    },
    onUseful(handler) {
      usefulListeners.push(handler);
    },
    get showUseful() {
      return useful.checked;
    },
    setUsefulCount(text) {
      usefulCount.hidden = text === null;
      usefulCount.textContent = text ?? '';
    },
  };
}

/** A positive finite length, else null (no domain). */
export function readMaxEdge(text: string): number | null {
  const v = Number(text);
  return text.trim() !== '' && Number.isFinite(v) && v > 0 ? v : null;
}

function clampEpsilon(v: number): number {
  return Number.isFinite(v) ? Math.min(0.99, Math.max(0.01, v)) : 0.25;
}
