// README: the browser with three.js (any bundler: Vite, webpack, Rollup, Parcel).
import * as THREE from 'three';
import { loadHodt } from 'hodt';
import { terrainGeometry } from 'hodt/three';

const hodt = await loadHodt(); // fetches hodt.wasm, which your bundler copies next to the JS
const xyz = Float64Array.from({ length: 3 * 2000 }, (_, i) => (i % 3 === 2 ? 0.2 : 1) * Math.random());
const terrain = hodt.terrain(xyz);
const best = terrain.solve('min-local-minima', { method: 'auto' });
const geometry = terrainGeometry(THREE, terrain.points, best.triangles, { up: 'y' }); // heights along +y
terrain.dispose();

const scene = new THREE.Scene().add(new THREE.Mesh(geometry, new THREE.MeshNormalMaterial()));
const camera = new THREE.PerspectiveCamera(45, innerWidth / innerHeight, 0.01, 10);
camera.position.set(0.5, 1.2, 0.6);
camera.lookAt(0.5, 0, -0.5);
const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setSize(innerWidth, innerHeight);
document.body.append(renderer.domElement);
renderer.render(scene, camera);
