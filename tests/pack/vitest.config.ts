// The npm package as users get it: `npx vitest run --config tests/pack/vitest.config.ts`
// after `npm run build`. Packs dist/ with npm pack, installs the tarball into an
// empty temporary project (no network), and uses it from Node, the CLI, TypeScript,
// and a Vite-bundled page in Chromium served with a strict Content-Security-Policy.
import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/pack/**/*.test.ts'],
    testTimeout: 120_000,
    hookTimeout: 180_000,
    fileParallelism: false,
  },
});
