import {
  Box3,
  Color,
  DirectionalLight,
  Group,
  HemisphereLight,
  PerspectiveCamera,
  Scene,
  Sphere,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';

/** A three.js view in a container: z-up scene, orbit controls, soft lighting,
 * rendering on demand. Add content to `world`. */
export interface Viewer {
  readonly scene: Scene;
  readonly world: Group;
  readonly camera: PerspectiveCamera;
  readonly renderer: WebGLRenderer;
  readonly controls: OrbitControls;
  /** Places the camera south-west of and above the points, all of them in view;
   * done again on resize until the user moves the camera. */
  frame(points: readonly Vector3[]): void;
  /** Frames the points again if any of them is out of view or under the view's
   * label (a point raised or moved by an edit); true if it did. */
  keepInView(points: readonly Vector3[]): boolean;
  /** Asks for a redraw on the next animation frame. */
  invalidate(): void;
  /** Draws now. */
  render(): void;
}

export function createViewer(container: HTMLElement): Viewer {
  const renderer = new WebGLRenderer({ antialias: true, alpha: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  renderer.setClearColor(new Color(0x000000), 0); // the page's gradient shows through
  container.appendChild(renderer.domElement);

  const scene = new Scene();
  const world = new Group();
  scene.add(world);

  const camera = new PerspectiveCamera(40, 1, 1, 10000);
  camera.up.set(0, 0, 1);

  // Sky and ground fill, and a sun from the north-west as in classic hillshades.
  scene.add(new HemisphereLight(0xf4f7ff, 0x8a7a66, 2.2));
  const sun = new DirectionalLight(0xfff4e2, 1.8);
  sun.position.set(-1, 1.2, 1.6);
  scene.add(sun);

  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = true;
  controls.dampingFactor = 0.12;
  controls.maxPolarAngle = Math.PI * 0.48;

  let dirty = true;
  const invalidate = () => (dirty = true);
  const buffer = new Vector2();
  const render = () => {
    dirty = false;
    // Fat lines are sized in pixels and need the drawing buffer size.
    renderer.getDrawingBufferSize(buffer);
    scene.traverse((o) => {
      const m = (o as { material?: unknown }).material;
      if (m instanceof LineMaterial) m.resolution.copy(buffer);
    });
    renderer.render(scene, camera);
  };
  controls.addEventListener('change', invalidate);
  controls.addEventListener('start', () => (framed = null));

  const project = () => {
    const w = container.clientWidth || 1;
    const h = container.clientHeight || 1;
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  };
  let framed: readonly Vector3[] | null = null; // reframed on resize until the user orbits
  const resize = () => {
    renderer.setSize(container.clientWidth || 1, container.clientHeight || 1, false);
    project();
    if (framed && container.clientWidth) frame(framed);
    invalidate();
  };
  new ResizeObserver(resize).observe(container);
  resize();

  renderer.setAnimationLoop(() => {
    if (!container.clientWidth) return; // hidden (plan view only)
    controls.update();
    if (dirty) render();
  });

  /** The top of the view the points may use, in normalised device coordinates:
   * below the view's label (a caption over the canvas's top-left corner). */
  function usableTop(): number {
    const label = container.querySelector<HTMLElement>('.view-label');
    const h = container.clientHeight;
    if (!label || !h) return 1;
    const inset = label.getBoundingClientRect().bottom - container.getBoundingClientRect().top + 6;
    return 1 - (2 * Math.max(0, Math.min(inset, h / 3))) / h;
  }

  function keepInView(points: readonly Vector3[]): boolean {
    // (Once the user has moved the camera, what it shows is theirs.)
    if (!framed || !container.clientWidth || points.length === 0) return false;
    camera.updateMatrixWorld();
    const top = usableTop();
    const p = new Vector3();
    for (const c of points) {
      p.copy(c).project(camera);
      if (p.x < -1 || p.x > 1 || p.y < -1 || p.y > top || p.z > 1) {
        frame(points);
        return true;
      }
    }
    return false;
  }

  function frame(points: readonly Vector3[]): void {
    framed = points;
    // The points fill the view below its label: its centre and half height in NDC.
    const top = usableTop();
    const centreY = (top - 1) / 2, halfY = (top + 1) / 2;
    const sphere = new Box3().setFromPoints(points as Vector3[]).getBoundingSphere(new Sphere());
    const dir = new Vector3(-0.45, -1, 1.15).normalize();
    const fill = 0.88; // fraction of the view the points span
    const target = sphere.center.clone();
    let distance = sphere.radius * 3;
    const p = new Vector3();
    const right = new Vector3();
    const up = new Vector3();
    for (let k = 0; k < 8; k++) {
      camera.position.copy(target).addScaledVector(dir, distance);
      camera.lookAt(target);
      camera.near = distance / 100;
      camera.far = distance * 10;
      project();
      camera.updateMatrixWorld();
      let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
      for (const c of points) {
        p.copy(c).project(camera);
        x0 = Math.min(x0, p.x);
        x1 = Math.max(x1, p.x);
        y0 = Math.min(y0, p.y);
        y1 = Math.max(y1, p.y);
      }
      // Pan so the points' screen box is centred, then zoom to fit.
      const halfH = distance * Math.tan((camera.fov * Math.PI) / 360);
      const halfW = halfH * camera.aspect;
      right.setFromMatrixColumn(camera.matrixWorld, 0);
      up.setFromMatrixColumn(camera.matrixWorld, 1);
      target.addScaledVector(right, ((x0 + x1) / 2) * halfW);
      target.addScaledVector(up, ((y0 + y1) / 2 - centreY) * halfH);
      distance *= Math.max((x1 - x0) / 2, (y1 - y0) / 2 / halfY) / fill;
    }
    controls.target.copy(target);
    controls.update();
    invalidate();
  }

  return {
    scene,
    world,
    camera,
    renderer,
    controls,
    frame,
    keepInView,
    invalidate,
    render,
  };
}
