import './style.css';
import { loadHodt } from 'hodt';
import { bindPanel } from './panel.ts';
import { readParams } from './params.ts';
import { describe, optimize } from './optimize.ts';
import { createTerrainView } from './terrainView.ts';
import { createViewer } from './viewer.ts';
import { volcanoPoints } from './volcano.ts';

const nextFrame = () => new Promise<void>((resolve) => requestAnimationFrame(() => resolve()));

async function main(): Promise<void> {
  const panel = bindPanel();
  panel.setStatus('Loading the WebAssembly module…', 'busy');
  const card = document.querySelector('.panel')!;
  const viewer = createViewer(document.getElementById('view')!, {
    insetLeft: () => card.getBoundingClientRect().right,
  });

  const hodt = await loadHodt();
  const params = readParams();
  const xyz = volcanoPoints(params.points);
  const terrain = hodt.terrain(xyz);
  const delaunay = terrain.delaunay();
  const quads = terrain.quads;
  const counts = {
    points: terrain.numPoints,
    triangles: delaunay.triangles.length / 3,
    quads: terrain.numQuads,
  };

  const view = createTerrainView(xyz, quads, terrain.quadOfTriangle, delaunay);
  viewer.world.add(view.object);
  viewer.frame(view.worldPoints);

  panel.setCounts(counts);
  panel.setObjectives(hodt.objectives);
  panel.setStatus('Showing the Delaunay triangulation. Pick an objective and optimise.');
  panel.onOptimize(async (id) => {
    panel.setBusy(true);
    panel.setStatus(`Optimising ${id}…`, 'busy');
    await nextFrame(); // let the status paint before the solver blocks
    const result = optimize(terrain, id, params.method);
    if (result.ok) {
      view.show(terrain.triangulation(result.solution.choice), result.solution.choice);
      viewer.invalidate();
      panel.setStatus(describe(result.solution), 'ok');
    } else {
      panel.setStatus(result.message, 'error');
    }
    panel.setBusy(false);
  });

  viewer.render();
  await nextFrame();
  window.__hodt = { ready: true, ...counts };
}

main().catch((e: unknown) => {
  const status = document.getElementById('status');
  if (status) {
    status.textContent = `Could not start: ${e instanceof Error ? e.message : String(e)}`;
    status.dataset.kind = 'error';
  }
  console.error(e);
});
