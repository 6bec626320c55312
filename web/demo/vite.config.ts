// Vite config of the demo (web/demo). Used by scripts/serve.mjs, tests/e2e and
// scripts/build.mjs (the static site: build/demo, shipped as dist/demo).
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const here = (p: string) => fileURLToPath(new URL(p, import.meta.url));
const repo = here('../../');

export default defineConfig({
  root: here('.'),
  // Relative URLs: the built site works from any static host, in any subfolder,
  // and from the npm package (`npx hodt demo`).
  base: './',
  resolve: {
    alias: [
      // The demo uses the library only through its public entry points.
      { find: /^hodt$/, replacement: here('../src/index.ts') },
      { find: /^hodt\/export$/, replacement: here('../src/export.ts') },
      // vega-datasets' package exports hide its data files; reach them directly.
      { find: 'vega-data', replacement: here('../../node_modules/vega-datasets/data') },
    ],
  },
  server: {
    host: '127.0.0.1',
    port: 5173,
    fs: { allow: [repo] },
  },
  // Pre-bundle up front so the first visit never triggers a reload.
  optimizeDeps: {
    entries: ['index.html'],
    include: ['three', 'fflate', 'three/examples/jsm/controls/OrbitControls.js', 'three/examples/jsm/lines/LineSegments2.js',
      'three/examples/jsm/lines/LineSegmentsGeometry.js', 'three/examples/jsm/lines/LineMaterial.js'],
  },
  // The solver runs in a module worker (src/solver/worker.ts).
  worker: { format: 'es' },
  build: {
    target: 'es2022',
    outDir: here('../../build/demo'),
    emptyOutDir: true,
    chunkSizeWarningLimit: 1000, // three.js and the volcano data: one chunk is fine
  },
});
