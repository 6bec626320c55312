// The browser tests: `npx vitest run --config tests/e2e/vitest.config.ts`.
// One file at a time: each starts its own Vite server and Chromium.
import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/e2e/**/*.test.ts'],
    testTimeout: 120_000,
    hookTimeout: 120_000,
    fileParallelism: false,
  },
});
