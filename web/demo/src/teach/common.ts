// What the teaching views' panes share: the paper's link, the pane, legends,
// buttons, the objective picker, the step controls, and a small terrain.
import type { Hodt, ObjectiveId } from 'hodt';
import { seededRandom } from '../terrains/rng.ts';
import { h } from '../ui/dom.ts';
import { OBJECTIVE_HELP } from '../ui/objectiveHelp.ts';
import { StepPlayer } from './stepPlayer.ts';
import type { TeachContext } from './view.ts';

export const PAPER_TITLE = 'M. van Kreveld, M. Löffler, R. I. Silveira: Optimization for first order Delaunay triangulations (Computational Geometry, 2010)';
export const PAPER_URL = 'https://dblp.org/search?q=Optimization+for+first+order+Delaunay+triangulations';

/** "Section 2.1 of the paper", linked. */
export function paperLink(section: string): HTMLAnchorElement {
  return h('a', { href: PAPER_URL, target: '_blank', rel: 'noopener', title: PAPER_TITLE, class: 'paper' }, `Section ${section} of the paper`);
}

/** A teaching pane: a side column (title, lead, controls) and a main area. */
export function createPane(id: string, title: string, lead: (Node | string)[]): { root: HTMLElement; side: HTMLElement; main: HTMLElement; caption: HTMLElement } {
  const side = h('div', { class: 'teach-side' }, h('h3', {}, title), h('p', { class: 'teach-lead' }, ...lead));
  const caption = h('span', { class: 'view-label teach-caption', id: `teach-${id}-caption` });
  const main = h('div', { class: 'teach-main' }, caption);
  const root = h('section', { class: 'teach-pane', id: `teach-${id}`, 'data-pane': id, role: 'tabpanel', hidden: true }, side, main);
  return { root, side, main, caption };
}

/** Colours of strongly connected components (no red: red marks contradictions). */
export const COMPONENT_COLORS = ['#1f77b4', '#9467bd', '#2ca02c', '#17becf', '#8c564b', '#e377c2', '#bcbd22', '#3f51b5'] as const;

/** A mark in a view's legend: a filled area, a line, a dashed line, a cross, a dot. */
export type LegendMark = 'fill' | 'line' | 'dash' | 'cross' | 'dot';

/** A line of a legend: the mark, its colour, what it means. */
export type LegendItem = readonly [LegendMark, string, string];

/** The legend of a view: every mark it draws, with what it means. */
export function legend(items: readonly LegendItem[]): HTMLUListElement {
  return h(
    'ul',
    { class: 'teach-legend' },
    ...items.map(([mark, color, label]) =>
      h('li', {}, mark === 'cross' ? h('i', { class: 'cross', style: `color: ${color}` }, '✕') : h('i', { class: mark === 'line' ? 'line thick' : mark, style: `--c: ${color}` }), label),
    ),
  );
}

/** A select of these objectives, by their names. */
export function objectiveOptions(id: string, ids: readonly ObjectiveId[], label: string): HTMLSelectElement {
  const select = h('select', { id, 'aria-label': label });
  select.replaceChildren(...ids.map((o) => h('option', { value: o }, OBJECTIVE_HELP[o].name)));
  return select;
}

/** The objective picker of a view: choosing one moves the sidebar too
 * (ctx.choose, which tells every view), then the view updates. */
export function objectiveSelect(ctx: TeachContext, id: string, ids: readonly ObjectiveId[], label: string, update: () => void): HTMLSelectElement {
  const select = objectiveOptions(id, ids, label);
  select.addEventListener('change', () => {
    ctx.choose({ objective: select.value as ObjectiveId });
    update();
  });
  return select;
}

/** The stepping of a view: a StepPlayer over the positions 0 to `last()` (`step`
 * shows a position, `intervalMs` apart while playing), the First / Prev / Play /
 * Next buttons that drive it, and the counter after them (`#<prefix>-counter`,
 * which the view writes). */
export function stepControls(
  prefix: string,
  o: { last: () => number; step: () => void; intervalMs: number; first: [string, string]; prev: [string, string]; next: [string, string]; play: string },
): { player: StepPlayer; counter: HTMLElement; controls: HTMLElement } {
  const player = new StepPlayer(o.last, o.step, o.intervalMs);
  const counter = h('span', { class: 'teach-counter', id: `${prefix}-counter` });
  const play = button(`${prefix}-play`, '▶ Play', o.play, () => player.toggle());
  player.attach(play);
  const controls = h(
    'div',
    { class: 'teach-controls' },
    button(`${prefix}-first`, o.first[0], o.first[1], () => player.go(0)),
    button(`${prefix}-prev`, o.prev[0], o.prev[1], () => player.go(player.pos - 1)),
    play,
    button(`${prefix}-next`, o.next[0], o.next[1], () => player.go(player.pos + 1)),
    counter,
  );
  return { player, counter, controls };
}

export function button(id: string, label: string, title: string, onClick: () => void, secondary = true): HTMLButtonElement {
  const b = h('button', { type: 'button', id, class: secondary ? 'secondary small' : 'small', title }, label);
  b.addEventListener('click', onClick);
  return b;
}

/** A small random terrain with between lo and hi flippable quads (found by
 * trying seeds in order, so always the same one). */
export function smallTerrain(hodt: Hodt, n: number, lo: number, hi: number, firstSeed = 1): Float64Array {
  for (let seed = firstSeed; seed < firstSeed + 500; seed++) {
    const random = seededRandom(seed);
    const xyz = new Float64Array(3 * n);
    const corners = [0, 0, 100, 0, 100, 100, 0, 100];
    for (let i = 0; i < n; i++) {
      xyz[3 * i] = i < 4 ? corners[2 * i]! : 8 + random() * 84;
      xyz[3 * i + 1] = i < 4 ? corners[2 * i + 1]! : 8 + random() * 84;
      xyz[3 * i + 2] = random() * 12;
    }
    const terrain = hodt.terrain(xyz);
    const m = terrain.numQuads;
    terrain.dispose();
    if (m >= lo && m <= hi) return xyz;
  }
  throw new Error('no small terrain found');
}
