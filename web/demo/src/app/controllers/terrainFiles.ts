// The terrain panel: built-in terrains, importing a file (button or drop) and
// exporting the points, the shown triangulation or the solution.
import { InputError, type Hodt, type ParsedPoints } from 'hodt';
import { download } from '../../io/download.ts';
import { meshFile } from '../../io/meshExport.ts';
import { pointsToCsv } from '../../io/pointsCsv.ts';
import { readTextFile } from '../../io/readTextFile.ts';
import { solutionToJson } from '../../io/solutionJson.ts';
import { TERRAINS } from '../../terrains/catalog.ts';
import { attachDropZone } from '../../ui/dropZone.ts';
import type { Notice } from '../../ui/notice.ts';
import type { ExportFormat, TerrainPanel } from '../../ui/terrainPanel.ts';
import type { AppState } from '../appState.ts';
import { dropDuplicateXY } from '../dedupe.ts';
import type { Store } from '../store.ts';
import type { Edits } from './edits.ts';

export function connectTerrainFiles(store: Store<AppState>, edits: Edits, hodt: Hodt, o: { panel: TerrainPanel; notice: Notice }): void {
  const { panel, notice } = o;

  async function importFile(file: File): Promise<void> {
    const refused = `Could not import ${file.name}`;
    let read: ParsedPoints;
    try {
      read = hodt.readPoints(await readTextFile(file), file.name);
    } catch (e) {
      if (!(e instanceof InputError) && !(e instanceof Error)) throw e;
      notice.show(`${refused}: ${e.message}. Your points are unchanged.`);
      return;
    }
    const { points: unique, removed } = dropDuplicateXY(read.points);
    // A raster with NODATA cells comes with its default domain; any other file
    // keeps the page's.
    const { settings } = store.get();
    const withDomain = read.maxEdge !== undefined ? { ...settings, maxEdge: read.maxEdge } : settings;
    if (!edits.commit(unique, `import ${file.name}`, { reframe: true, select: null, refused, settings: withDomain })) return;
    const notes: string[] = [];
    if (removed > 0) notes.push(`dropped ${removed} point${removed === 1 ? '' : 's'} at the same (x, y) as an earlier one`);
    if (read.maxEdge !== undefined) notes.push(`it has NODATA cells, so triangles with an edge longer than ${read.maxEdge} are outside the domain (greyed, not measured; see Longest edge)`);
    if (notes.length > 0) notice.show(`Imported ${file.name}: ${notes.join('; ')}.`, 'info');
  }

  function exportAs(format: ExportFormat): void {
    const { settings, solution, points, shown, committed } = store.get();
    const base = `hodt-${settings.objective}`;
    const about = solution ? `${solution.objective} = ${solution.value} (Delaunay ${solution.delaunayValue})` : 'Delaunay triangulation';
    if (format === 'csv') download('hodt-points.csv', pointsToCsv(points), 'text/csv');
    else if (format !== 'json') {
      const { bytes, type } = meshFile(format, shown!, `hodt: ${about}`, settings.maxEdge !== null);
      download(`${base}.${format}`, bytes, type);
    } else if (solution) download(`${base}.json`, solutionToJson(solution, committed.terrain), 'application/json');
    else notice.show('No solution to export yet: wait for the solver to finish.', 'info');
  }

  panel.set(store.get().source);
  panel.onGenerate((s) => {
    edits.commit(TERRAINS[s.kind].make(s.count, s.seed), `load ${TERRAINS[s.kind].label.toLowerCase()}`, { source: s, reframe: true, select: null });
  });
  panel.onImport((f) => void importFile(f));
  panel.onExport(exportAs);
  attachDropZone((f) => void importFile(f));
  store.subscribe((s) => panel.set(s.source), ['points', 'source']);
}
