// A guided route through the Teach tabs for a first lesson: what to click, what
// to notice. Each step opens its tab (and loads its example where it has one).
import { h } from '../ui/dom.ts';
import { PAPER_TITLE, PAPER_URL } from './common.ts';
import type { TeachTab } from './teachPanel.ts';

interface Step {
  tab: TeachTab;
  title: string;
  /** The button of the view that loads its example, if any. */
  example?: string;
  doThis: string;
  notice: string;
}

const STEPS: readonly Step[] = [
  {
    tab: 'brute',
    title: 'All triangulations',
    example: 'brute-small',
    doThis: 'Load the small terrain, then pick objectives in the sidebar.',
    notice: 'Every first order triangulation is one choice of diagonal per teal quad: 2^m of them. The best one (gold frame) changes with the objective, and Delaunay is rarely it.',
  },
  {
    tab: 'sat',
    title: '2-SAT search (Section 2.1)',
    example: 'sat-small',
    doThis: 'Load the example, then press Play.',
    notice: 'Each test asks "can every pair stay below t?". Quads with one bad diagonal are forced; the rest become clauses, and a red ✕ (both diagonals in one strongly connected component) means no. The search tests the lower bound first, then halves the candidates each time.',
  },
  {
    tab: 'baker',
    title: 'Baker’s layers (Section 4)',
    doThis: 'Try ε = 0.5, then 0.25, and step through the shifts.',
    notice: 'Smaller ε means more layers per period (λ) and more shifts; every shift’s value is a real triangulation and its bound caps the optimum, so the gap is proven, not guessed.',
  },
  {
    tab: 'gadget',
    title: 'Why most convex edges is NP-hard (Section 3.3)',
    example: 'gadget-build',
    doThis: 'Build the default formula, then change a clause and build again.',
    notice: 'The optimum minus a constant is the number of clauses the best assignment satisfies: solving this terrain solves MAX-2-SAT.',
  },
  {
    tab: 'order',
    title: 'Higher order (Section 4.3)',
    doThis: 'Pick “Fewest pits” in the sidebar, then press Play to step k from 1 to 8.',
    notice: 'Regions cut by the fixed edges merge as k grows, each with more triangulations, and the pits (red dots) disappear one after another.',
  },
];

export function createLesson(select: (tab: TeachTab) => void): HTMLElement {
  const items = STEPS.map((s, i) => {
    const go = h('button', { type: 'button', class: 'secondary small', id: `lesson-${s.tab}`, title: `Open ${s.title}` }, 'Go');
    go.addEventListener('click', () => {
      select(s.tab);
      if (s.example) document.getElementById(s.example)?.click();
    });
    return h('li', {}, h('b', {}, `${i + 1}. ${s.title}. `), go, h('br', {}), h('span', {}, s.doThis, ' '), h('span', { class: 'muted' }, `Notice: ${s.notice}`));
  });
  return h(
    'details',
    { class: 'teach-lesson', id: 'teach-lesson' },
    h('summary', {}, 'A first lesson in five steps'),
    h('ol', {}, ...items),
    h('p', { class: 'muted' }, 'From ', h('a', { href: PAPER_URL, target: '_blank', rel: 'noopener' }, PAPER_TITLE), '.'),
  );
}
