import type { ObjectiveInfo, ProgressInfo, RegionExplanation, Solution } from 'hodt';
import { countRegions, describeRegions, detailsWithoutRegionSummary } from '../app/regionCount.ts';
import { byId, h } from './dom.ts';
import { formatValue, OBJECTIVE_HELP } from './objectiveHelp.ts';

/** The outcome of the current solve: a progress bar with Cancel while it runs,
 * then the value against Delaunay, the proof (optimal, or bound and gap), time
 * and flips; or why it failed. */
export interface ResultCard {
  running(objective: ObjectiveInfo, onCancel: () => void): void;
  /** The solver's phase, and how far it is when the phase knows its size. */
  progress(info: ProgressInfo): void;
  /** regions: the library's regions of the order (order k >= 2). */
  solved(objective: ObjectiveInfo, s: Solution, numQuads: number, regions?: RegionExplanation | null): void;
  failed(objective: ObjectiveInfo, message: string, order?: number): void;
  cancelled(objective: ObjectiveInfo): void;
}

export function createResultCard(): ResultCard {
  const root = byId('result');
  let timer = 0;
  const stopTimer = () => {
    clearInterval(timer);
    timer = 0;
  };

  return {
    running(o, onCancel) {
      stopTimer();
      const started = performance.now();
      const elapsed = h('span', { class: 'elapsed' }, '0.0 s');
      const cancel = h('button', { type: 'button', id: 'cancel', class: 'secondary small' }, 'Cancel');
      cancel.addEventListener('click', onCancel);
      root.dataset.state = 'running';
      root.replaceChildren(
        h('div', { class: 'progress', id: 'progress', role: 'progressbar', 'aria-label': 'Solving' }, h('i')),
        h('p', { class: 'line' }, `Solving ${OBJECTIVE_HELP[o.id].name.toLowerCase()}… `, h('span', { class: 'phase', id: 'phase' }), elapsed, ' ', cancel),
      );
      timer = window.setInterval(() => {
        elapsed.textContent = `${((performance.now() - started) / 1000).toFixed(1)} s`;
      }, 100);
    },
    progress(info) {
      const bar = root.querySelector<HTMLElement>('#progress');
      const phase = root.querySelector<HTMLElement>('#phase');
      if (!bar || !phase) return;
      const left = info.secondsLeft === null ? '' : `, about ${Math.ceil(info.secondsLeft)} s left`;
      phase.textContent = `${info.phase}${left} · `;
      // A phase that does not know its size shows that work goes on, not a share.
      if (!info.sized) {
        delete bar.dataset.determinate;
        bar.removeAttribute('aria-valuenow');
        bar.querySelector('i')!.style.width = '';
        return;
      }
      const fraction = Math.min(1, Math.max(0, info.fraction));
      bar.dataset.determinate = '';
      bar.setAttribute('aria-valuenow', String(Math.round(fraction * 100)));
      bar.querySelector('i')!.style.width = `${(fraction * 100).toFixed(1)}%`;
    },
    solved(o, s, numQuads, regions = null) {
      stopTimer();
      root.dataset.state = 'solved';
      const better = s.sense === 'min' ? s.value < s.delaunayValue : s.value > s.delaunayValue;
      const same = s.value === s.delaunayValue;
      const change = same ? 'same as Delaunay' : `${better ? 'better' : 'worse'} than Delaunay (${formatValue(o.id, s.delaunayValue)})`;
      const details = s.order > 1 ? detailsWithoutRegionSummary(s.details) : s.details;
      const proof = s.optimal
        ? h('span', { class: 'badge ok' }, '✓ proven optimal')
        : s.bound !== null
          ? h('span', { class: 'badge approx' }, `optimum ${s.sense === 'min' ? '≥' : '≤'} ${formatValue(o.id, s.bound)} · gap ${gap(s)}`)
          : h('span', { class: 'badge approx' }, 'not proven optimal');
      root.replaceChildren(
        h(
          'p',
          { class: 'value' },
          h('b', { id: 'result-value', 'data-value': String(s.value), title: String(s.value) }, formatValue(o.id, s.value)),
          h('span', { class: same ? 'delta' : better ? 'delta good' : 'delta bad' }, change),
        ),
        h('p', { class: 'line' }, proof),
        h(
          'p',
          { class: 'line muted' },
          s.order > 1
            ? `order ${s.order} · ${s.flipped} edge${s.flipped === 1 ? '' : 's'} not in Delaunay · ${s.method} · ${formatMs(s.timeMs)}`
            : `${s.flipped} of ${numQuads} quads flipped · ${s.method} · ${formatMs(s.timeMs)}`,
          s.critical ? h('span', { class: 'chip critical' }, 'worst pair') : null,
        ),
        regions ? h('p', { class: 'line muted', id: 'result-regions' }, `${describeRegions(countRegions(regions))}.`) : '',
        details ? h('p', { class: 'line muted' }, details) : '',
      );
    },
    failed(o, message, order = 1) {
      stopTimer();
      root.dataset.state = 'failed';
      root.replaceChildren(
        h('p', { class: 'line error' }, `Could not optimise ${o.id}: ${message}`),
        h('p', { class: 'line muted' }, order > 1 ? 'Showing the Delaunay triangulation.' : 'Showing the Delaunay triangulation. Try method auto or approximation.'),
      );
    },
    cancelled(o) {
      stopTimer();
      root.dataset.state = 'cancelled';
      root.replaceChildren(
        h('p', { class: 'line' }, `Cancelled ${o.id}. Showing the Delaunay triangulation.`),
      );
    },
  };
}

/** Relative gap between the value and the proven bound on the optimum. */
function gap(s: Solution): string {
  if (s.bound === null) return '—';
  const g = Math.abs(s.value - s.bound) / Math.max(Math.abs(s.bound), Math.abs(s.value), 1e-300);
  return `${(g * 100).toFixed(g < 0.1 ? 1 : 0)}%`;
}

function formatMs(ms: number): string {
  return ms < 1 ? `${ms.toFixed(2)} ms` : ms < 1000 ? `${ms.toFixed(0)} ms` : `${(ms / 1000).toFixed(2)} s`;
}
