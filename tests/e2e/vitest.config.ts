// The browser tests: `npx vitest run --config tests/e2e/vitest.config.ts`.
// One file at a time: each browser test starts its own Vite server and Chromium.
// The demo's pure modules (link format, exports) are tested here in Node too.
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

export default defineConfig({
  resolve: {
    alias: [
      { find: /^hodt$/, replacement: fileURLToPath(new URL('../../web/src/index.ts', import.meta.url)) },
      { find: /^hodt\/export$/, replacement: fileURLToPath(new URL('../../web/src/export.ts', import.meta.url)) },
    ],
  },
  test: {
    include: ['tests/e2e/**/*.test.ts'],
    testTimeout: 120_000,
    hookTimeout: 120_000,
    fileParallelism: false,
    // Software WebGL on a shared 2-core machine: a browser test that times out is
    // tried once more; a failure that repeats fails the run.
    retry: 1,
  },
});
