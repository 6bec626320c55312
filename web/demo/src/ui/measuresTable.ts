import type { ObjectiveId, ObjectiveInfo, ObjectiveValues } from 'hodt';
import { byId, h } from './dom.ts';
import { formatValue, OBJECTIVE_HELP } from './objectiveHelp.ts';

/** All 13 measures of the shown triangulation next to the Delaunay ones, with
 * the current objective's row highlighted; green where better, red where worse.
 * Clicking a row optimises that measure. */
export function renderMeasures(
  objectives: readonly ObjectiveInfo[],
  current: ObjectiveValues,
  delaunay: ObjectiveValues,
  active: ObjectiveId,
  choose: (id: ObjectiveId) => void,
): void {
  const table = byId<HTMLTableElement>('measures');
  const head = h('thead', {}, h('tr', {}, h('th', {}, 'measure'), h('th', {}, 'shown'), h('th', {}, 'Delaunay')));
  const body = h('tbody');
  for (const o of objectives) {
    const v = current[o.id];
    const d = delaunay[o.id];
    const better = o.sense === 'min' ? v < d : v > d;
    const worse = o.sense === 'min' ? v > d : v < d;
    const arrow = o.sense === 'min' ? '↓' : '↑';
    const row = h(
        'tr',
        { class: o.id === active ? 'active' : undefined, 'data-id': o.id, title: `${OBJECTIVE_HELP[o.id].help} (Click to optimise ${o.id}.)` },
        h('td', {}, `${OBJECTIVE_HELP[o.id].measure} `, h('span', { class: 'sense' }, arrow)),
        h('td', { class: better ? 'good' : worse ? 'bad' : undefined, 'data-value': String(v) }, formatValue(o.id, v)),
        h('td', { 'data-value': String(d) }, formatValue(o.id, d)),
    );
    row.addEventListener('click', () => choose(o.id));
    body.append(row);
  }
  table.replaceChildren(head, body);
}
