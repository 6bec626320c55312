// The "Teach" tab: seven views of the paper's ideas, one visible at a time.
import { byId, h } from '../ui/dom.ts';
import { createBakerView } from './bakerView.ts';
import { createBruteView } from './bruteView.ts';
import type { TeachContext, TeachView } from './common.ts';
import { createDegreeView } from './degreeView.ts';
import { createGadgetView } from './gadgetView.ts';
import { createLesson } from './lesson.ts';
import { createMixedView } from './mixedView.ts';
import { createOrderView } from './orderView.ts';
import { createSatView } from './satView.ts';

export const TEACH_TABS = ['sat', 'baker', 'gadget', 'degree', 'mixed', 'brute', 'order'] as const;
export type TeachTab = (typeof TEACH_TABS)[number];

export interface TeachPanel {
  /** The Teach tab is shown (or hidden). */
  setVisible(visible: boolean): void;
  /** The page's terrain or settings changed. */
  changed(): void;
  select(tab: TeachTab): void;
}

export function createTeachPanel(ctx: TeachContext): TeachPanel {
  const root = byId('teach');
  const views: TeachView[] = [createSatView(ctx), createBakerView(ctx), createGadgetView(ctx), createDegreeView(ctx), createMixedView(ctx), createBruteView(ctx), createOrderView(ctx)];
  const tabs = views.map((v) => {
    const b = h('button', { type: 'button', role: 'tab', id: `teach-tab-${v.id}`, 'data-teach': v.id, 'aria-selected': 'false', 'aria-controls': `teach-${v.id}` }, v.label);
    b.addEventListener('click', () => select(v.id as TeachTab));
    return b;
  });
  root.append(h('nav', { class: 'teach-tabs', role: 'tablist', 'aria-label': 'Teaching views' }, ...tabs), createLesson(ctx, (tab) => select(tab)), ...views.map((v) => v.root));
  let visible = false;
  let current: TeachTab = 'sat';

  function select(tab: TeachTab): void {
    const before = current;
    current = tab;
    views.forEach((v, i) => {
      const on = v.id === tab;
      v.root.hidden = !on;
      tabs[i]!.setAttribute('aria-selected', String(on));
      if (!on && v.id === before) v.deactivate();
    });
    if (visible) views.find((v) => v.id === tab)!.activate();
  }

  window.__hodtTeach = {
    get visible() {
      return visible;
    },
    get tab() {
      return current;
    },
    view: (id: string) => views.find((v) => v.id === id)?.hooks() ?? null,
  };
  select('sat');

  return {
    setVisible(on) {
      if (on === visible) return;
      visible = on;
      const view = views.find((v) => v.id === current)!;
      if (on) view.activate();
      else view.deactivate();
    },
    changed() {
      for (const v of views) v.changed();
    },
    select,
  };
}
