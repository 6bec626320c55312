import { Vector2 } from 'three';
import type { TerrainScene } from './terrainScene.ts';
import type { Viewer } from './viewer.ts';

/** A click (without dragging: the orbit controls' gestures are not clicks) on
 * the 3D terrain picks the nearest point of the triangle under it, or null. */
export function onClickPick(viewer: Viewer, scene: TerrainScene, pick: (index: number | null) => void): void {
  const canvas = viewer.renderer.domElement;
  let down: { x: number; y: number } | null = null;
  canvas.addEventListener('pointerdown', (e) => (down = { x: e.clientX, y: e.clientY }));
  canvas.addEventListener('pointerup', (e) => {
    if (!down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
    const r = canvas.getBoundingClientRect();
    const ndc = { x: ((e.clientX - r.left) / r.width) * 2 - 1, y: -((e.clientY - r.top) / r.height) * 2 + 1 };
    pick(scene.pick(new Vector2(ndc.x, ndc.y), viewer.camera));
  });
}
