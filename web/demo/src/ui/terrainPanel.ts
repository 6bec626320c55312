import { TERRAIN_KINDS, TERRAINS, type TerrainKind } from '../terrains/catalog.ts';
import { byId, h } from './dom.ts';

export interface TerrainSource {
  kind: TerrainKind;
  count: number;
  seed: number;
}

export type ExportFormat = 'csv' | 'obj' | 'ply' | 'geojson' | 'glb' | 'json';

/** Built-in terrain picker with point count and seed sliders; import and export
 * buttons. Sliders regenerate when released. */
export interface TerrainPanel {
  /** Shows a source, or null for points that came from a file or were edited. */
  set(source: TerrainSource | null): void;
  onGenerate(handler: (source: TerrainSource) => void): void;
  onImport(handler: (file: File) => void): void;
  onExport(handler: (format: ExportFormat) => void): void;
}

const CUSTOM = 'custom';

export function createTerrainPanel(): TerrainPanel {
  const kind = byId<HTMLSelectElement>('terrain-kind');
  const about = byId('terrain-about');
  const count = byId<HTMLInputElement>('terrain-count');
  const seed = byId<HTMLInputElement>('terrain-seed');
  const countOut = byId<HTMLOutputElement>('terrain-count-value');
  const seedOut = byId<HTMLOutputElement>('terrain-seed-value');
  const file = byId<HTMLInputElement>('import-file');

  kind.replaceChildren(
    ...TERRAIN_KINDS.map((k) => h('option', { value: k }, TERRAINS[k].label)),
    h('option', { value: CUSTOM, disabled: true }, 'Your points (imported or edited)'),
  );
  const showOutputs = () => {
    countOut.value = count.value;
    seedOut.value = seed.value;
  };
  const showAbout = () => {
    about.textContent = kind.value === CUSTOM ? 'Points from a file, a link or your edits. Pick a source above to start over.' : TERRAINS[kind.value as TerrainKind].about;
  };
  count.addEventListener('input', showOutputs);
  seed.addEventListener('input', showOutputs);

  const generateHandlers: ((s: TerrainSource) => void)[] = [];
  const generate = () => {
    if (kind.value === CUSTOM) kind.value = TERRAIN_KINDS[0]!;
    showAbout();
    const s = { kind: kind.value as TerrainKind, count: Number(count.value), seed: Number(seed.value) };
    for (const g of generateHandlers) g(s);
  };
  kind.addEventListener('change', generate);
  count.addEventListener('change', generate);
  seed.addEventListener('change', generate);

  const importHandlers: ((f: File) => void)[] = [];
  byId('import').addEventListener('click', () => file.click());
  file.addEventListener('change', () => {
    const f = file.files?.[0];
    file.value = '';
    if (f) for (const i of importHandlers) i(f);
  });

  const exportHandlers: ((f: ExportFormat) => void)[] = [];
  for (const format of ['csv', 'obj', 'ply', 'geojson', 'glb', 'json'] as const) {
    byId(`export-${format}`).addEventListener('click', () => exportHandlers.forEach((e) => e(format)));
  }

  return {
    set(source) {
      if (source) {
        kind.value = source.kind;
        count.value = String(source.count);
        seed.value = String(source.seed);
      } else {
        kind.value = CUSTOM;
      }
      showOutputs();
      showAbout();
    },
    onGenerate: (f) => generateHandlers.push(f),
    onImport: (f) => importHandlers.push(f),
    onExport: (f) => exportHandlers.push(f),
  };
}
