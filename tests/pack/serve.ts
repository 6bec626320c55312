// A static file server like a production host: optionally under a subfolder
// (`prefix`), optionally sending a Content-Security-Policy header with every
// response (pages, scripts, workers, wasm), like a strict one.
import { readFile } from 'node:fs/promises';
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { extname, join, normalize } from 'node:path';

const types: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript',
  '.mjs': 'text/javascript',
  '.wasm': 'application/wasm',
  '.css': 'text/css',
};

export interface StaticServer {
  url: string;
  close(): Promise<void>;
}

export async function serveStatic(dir: string, options: { csp?: string; prefix?: string } = {}): Promise<StaticServer> {
  const prefix = options.prefix ?? '/';
  const server: Server = createServer(async (req, res) => {
    const url = new URL(req.url ?? '/', 'http://x').pathname;
    if (url === '/favicon.ico' || !url.startsWith(prefix)) return void res.writeHead(url === '/favicon.ico' ? 204 : 404).end();
    const path = normalize(`/${decodeURIComponent(url.slice(prefix.length))}`).replace(/^(\.\.[/\\])+/, '');
    const file = join(dir, path.endsWith('/') ? `${path}index.html` : path);
    try {
      const body = await readFile(file);
      const headers: Record<string, string> = { 'content-type': types[extname(file)] ?? 'application/octet-stream' };
      if (options.csp) headers['content-security-policy'] = options.csp;
      res.writeHead(200, headers).end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return { url: `http://127.0.0.1:${port}${prefix}`, close: () => new Promise((resolve) => server.close(() => resolve())) };
}
