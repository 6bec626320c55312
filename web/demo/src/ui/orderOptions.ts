import { MAX_ORDER } from '../app/settings.ts';
import { h } from './dom.ts';

/** The options of an order select, 1 to MAX_ORDER, each titled by what it allows. */
export function orderOptions(): HTMLOptionElement[] {
  return Array.from({ length: MAX_ORDER }, (_, i) =>
    h('option', { value: i + 1, title: i === 0 ? 'First order: one diagonal per flippable quad' : `At most ${i + 1} points in every circumcircle` }, i === 0 ? '1 · first order' : String(i + 1)),
  );
}
