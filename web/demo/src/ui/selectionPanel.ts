import { byId, h } from './dom.ts';

export interface SelectedPoint {
  index: number;
  x: number;
  y: number;
  z: number;
  /** One line on its class, extremum and degree. */
  about: string;
}

/** The selected point: editable x, y, z fields, its class and a Delete button. */
export interface SelectionPanel {
  show(p: SelectedPoint | null): void;
  onEdit(handler: (index: number, x: number, y: number, z: number) => void): void;
  onDelete(handler: (index: number) => void): void;
}

export function createSelectionPanel(): SelectionPanel {
  const root = byId('selection');
  const editHandlers: ((i: number, x: number, y: number, z: number) => void)[] = [];
  const deleteHandlers: ((i: number) => void)[] = [];

  return {
    show(p) {
      if (!p) {
        root.replaceChildren(h('p', { class: 'help' }, 'None. Click a point in either view to select it.'));
        return;
      }
      const field = (name: 'x' | 'y' | 'z', value: number) =>
        h('label', { class: 'coord' }, name, h('input', { type: 'number', step: 'any', id: `point-${name}`, value: String(value) }));
      const fx = field('x', p.x);
      const fy = field('y', p.y);
      const fz = field('z', p.z);
      const commit = () => {
        const [x, y, z] = [fx, fy, fz].map((f) => Number(f.querySelector('input')!.value));
        if ([x, y, z].every((v) => Number.isFinite(v))) editHandlers.forEach((e) => e(p.index, x!, y!, z!));
      };
      for (const f of [fx, fy, fz]) f.querySelector('input')!.addEventListener('change', commit);
      const remove = h('button', { type: 'button', id: 'delete-point', class: 'secondary small', title: 'Delete key' }, 'Delete');
      remove.addEventListener('click', () => deleteHandlers.forEach((d) => d(p.index)));
      root.replaceChildren(h('div', { class: 'coords' }, fx, fy, fz), h('p', { class: 'help' }, `${p.about}. `, remove));
    },
    onEdit: (f) => editHandlers.push(f),
    onDelete: (f) => deleteHandlers.push(f),
  };
}
