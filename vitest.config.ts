import { defineConfig } from 'vitest/config';

// Unit and contract tests of the library and CLI, against the real wasm in Node.
export default defineConfig({
  test: {
    include: ['tests/js/**/*.test.ts'],
    testTimeout: 120_000,
    hookTimeout: 120_000,
  },
});
