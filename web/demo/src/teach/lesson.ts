// A guided route through the Teach tabs for a first lesson: what to click, what
// to notice. Each step opens its tab and loads the terrain made for it
// (lessonSteps.ts), or builds the view's own instance.
import { TERRAINS } from '../terrains/catalog.ts';
import { h } from '../ui/dom.ts';
import { PAPER_TITLE, PAPER_URL } from './common.ts';
import { LESSON_STEPS, type LessonStep } from './lessonSteps.ts';
import type { TeachContext } from './view.ts';
import type { TeachTab } from './views.ts';

/** What a step's button loads, for its tooltip. */
function loads(s: LessonStep): string {
  if (!s.terrain) return `Open ${s.title} and build its instance`;
  const t = s.terrain;
  const n = TERRAINS[t.kind].make(t.count, t.seed).length / 3;
  return `Open ${s.title} with ${n} points (${TERRAINS[t.kind].label.toLowerCase()}, seed ${t.seed})`;
}

export function createLesson(ctx: TeachContext, select: (tab: TeachTab) => void): HTMLElement {
  const items = LESSON_STEPS.map((s, i) => {
    const go = h('button', { type: 'button', class: 'secondary small', id: `lesson-${s.tab}`, title: loads(s) }, 'Go');
    go.addEventListener('click', () => {
      select(s.tab);
      if (s.terrain) {
        const t = s.terrain;
        ctx.load(TERRAINS[t.kind].make(t.count, t.seed), `load the lesson's ${s.title.toLowerCase()} terrain`, s.objective, t);
      }
      if (s.epsilon !== undefined) ctx.choose({ epsilon: s.epsilon });
      for (const [id, value] of Object.entries(s.controls ?? {})) {
        const select = document.getElementById(id);
        if (!(select instanceof HTMLSelectElement) || select.value === value) continue;
        select.value = value;
        select.dispatchEvent(new Event('change'));
      }
      if (s.build) document.getElementById(s.build)?.click();
    });
    return h('li', {}, h('b', {}, `${i + 1}. ${s.title}. `), go, h('br', {}), h('span', {}, s.doThis, ' '), h('span', { class: 'muted' }, `Notice: ${s.notice}`));
  });
  return h(
    'details',
    { class: 'teach-lesson', id: 'teach-lesson' },
    h('summary', {}, `A first lesson in ${LESSON_STEPS.length} steps`),
    h('ol', {}, ...items),
    h('p', { class: 'muted' }, 'From ', h('a', { href: PAPER_URL, target: '_blank', rel: 'noopener' }, PAPER_TITLE), '.'),
  );
}
