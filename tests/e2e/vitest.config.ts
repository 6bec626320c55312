// Optional config for the browser tests: `npx vitest run --config tests/e2e/vitest.config.ts`.
// demo.test.ts sets its own timeouts, so `npx vitest run tests/e2e` works without it.
import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/e2e/**/*.test.ts'],
    testTimeout: 120_000,
    hookTimeout: 120_000,
    fileParallelism: false,
  },
});
