// Serves the demo (web/demo) with Vite's dev server on http://127.0.0.1:5173/
// (the next free port if that one is taken). Run `npm start`, or this file after
// `npm run build` has produced web/src/wasm/hodt.{mjs,wasm}.
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { createServer } from 'vite';

const root = fileURLToPath(new URL('..', import.meta.url));
if (!existsSync(`${root}/web/src/wasm/hodt.wasm`)) {
  console.error('web/src/wasm/hodt.wasm is missing: run `npm run build` first.');
  process.exit(1);
}

const server = await createServer({
  configFile: `${root}/web/demo/vite.config.ts`,
  server: { host: '127.0.0.1', port: 5173 },
});
await server.listen();
const url = server.resolvedUrls?.local[0] ?? 'http://127.0.0.1:5173/';
console.log(`\n  hodt demo: ${url}\n  (Ctrl+C to stop)`);

for (const signal of ['SIGINT', 'SIGTERM']) {
  process.on(signal, async () => {
    await server.close();
    process.exit(0);
  });
}
