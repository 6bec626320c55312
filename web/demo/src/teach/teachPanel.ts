// The "Teach" tab: the views of views.ts, one visible at a time, and the lesson.
import { byId, h } from '../ui/dom.ts';
import { createLesson } from './lesson.ts';
import type { TeachContext } from './view.ts';
import { TEACH_VIEWS, type TeachTab } from './views.ts';

export type { TeachTab };

export interface TeachPanel {
  /** The Teach tab is shown (or hidden). */
  setVisible(visible: boolean): void;
  /** The page's terrain or settings changed. */
  changed(): void;
  select(tab: TeachTab): void;
}

export function createTeachPanel(ctx: TeachContext): TeachPanel {
  const root = byId('teach');
  const views = TEACH_VIEWS.map((spec) => ({ id: spec.id as TeachTab, view: spec.create(ctx) }));
  const tabs = TEACH_VIEWS.map((spec) => {
    const b = h('button', { type: 'button', role: 'tab', id: `teach-tab-${spec.id}`, 'data-teach': spec.id, 'aria-selected': 'false', 'aria-controls': `teach-${spec.id}` }, spec.label);
    b.addEventListener('click', () => select(spec.id));
    return b;
  });
  root.append(h('nav', { class: 'teach-tabs', role: 'tablist', 'aria-label': 'Teaching views' }, ...tabs), createLesson(ctx, (tab) => select(tab)), ...views.map((v) => v.view.root));
  let visible = false;
  let current: TeachTab = 'sat';

  function select(tab: TeachTab): void {
    const before = current;
    current = tab;
    views.forEach((v, i) => {
      const on = v.id === tab;
      v.view.root.hidden = !on;
      tabs[i]!.setAttribute('aria-selected', String(on));
      if (!on && v.id === before) v.view.deactivate();
    });
    if (visible) shown().activate();
  }

  const shown = () => views.find((v) => v.id === current)!.view;

  window.__hodtTeach = {
    get visible() {
      return visible;
    },
    get tab() {
      return current;
    },
    view: (id: string) => views.find((v) => v.id === id)?.view.hooks() ?? null,
  };
  select('sat');

  return {
    setVisible(on) {
      if (on === visible) return;
      visible = on;
      if (on) shown().activate();
      else shown().deactivate();
    },
    changed() {
      for (const v of views) v.view.changed();
    },
    select,
  };
}
