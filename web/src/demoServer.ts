// `hodt demo`: serves the teaching demo that ships in the package (dist/demo, a
// static site with relative paths) on 127.0.0.1 with Node alone, and opens it in
// the default browser unless --no-open.
import { spawn } from 'node:child_process';
import { readFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { extname, join, normalize, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript',
  '.mjs': 'text/javascript',
  '.css': 'text/css',
  '.wasm': 'application/wasm',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.csv': 'text/csv',
  '.txt': 'text/plain; charset=utf-8',
};

const USAGE = 'usage: hodt demo [--port N] [--no-open] [--help]';

/** What `hodt demo --help` prints. */
export const DEMO_HELP = `${USAGE}

Serves the teaching demo that ships in the package on http://127.0.0.1:PORT/ and
opens it in the default browser. Ctrl+C stops it.

  --port N     the port to listen on, 0 to 65535 (default 5173; 0: any free one)
  --no-open    do not open a browser, only print the address
  --help, -h   print this help and exit
`;

export interface DemoOptions {
  port: number;
  open: boolean;
  /** --help: print DEMO_HELP and serve nothing. */
  help: boolean;
}

/** The options of `hodt demo`, or a one-line error. */
export function demoOptions(args: string[]): DemoOptions | string {
  const options: DemoOptions = { port: 5173, open: true, help: false };
  for (let i = 0; i < args.length; i++) {
    const a = args[i]!;
    if (a === '--help' || a === '-h') options.help = true;
    else if (a === '--no-open') options.open = false;
    else if (a === '--port') {
      const v = args[++i];
      const port = Number(v);
      if (v === undefined || !/^\d+$/.test(v) || port > 65535) return `hodt demo: --port needs a port number 0 to 65535, got ${v === undefined ? 'nothing' : `'${v}'`}; ${USAGE}`;
      options.port = port;
    } else return `hodt demo: unknown option '${a}'; ${USAGE}`;
  }
  return options;
}

/** Serves dir until the process is interrupted; resolves once it has stopped. */
export async function serveDemo(options: DemoOptions, dir = fileURLToPath(new URL('./demo/', import.meta.url))): Promise<void> {
  const root = normalize(dir);
  const server = createServer(async (req, res) => {
    let path: string;
    try {
      path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
    } catch {
      return void res.writeHead(400).end(); // a malformed address must not stop the server
    }
    const file = normalize(join(root, path.endsWith('/') ? `${path}index.html` : path));
    if (!file.startsWith(root.endsWith(sep) ? root : root + sep)) return void res.writeHead(403).end();
    try {
      const body = await readFile(file);
      res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain' }).end('not found');
    }
  });
  await new Promise<void>((resolve, reject) => {
    server.once('error', reject);
    server.listen(options.port, '127.0.0.1', resolve);
  });
  const url = `http://127.0.0.1:${(server.address() as AddressInfo).port}/`;
  process.stdout.write(`hodt demo: ${url} (Ctrl+C to stop)\n`);
  if (options.open) openBrowser(url);
  await new Promise<void>((resolve) => {
    const stop = () => server.close(() => resolve());
    process.once('SIGINT', stop);
    process.once('SIGTERM', stop);
  });
}

/** Best effort: the platform's "open this URL" command; the URL is printed anyway. */
function openBrowser(url: string): void {
  const command = process.platform === 'darwin' ? 'open' : process.platform === 'win32' ? 'cmd' : 'xdg-open';
  const args = process.platform === 'win32' ? ['/c', 'start', '', url] : [url];
  try {
    const child = spawn(command, args, { stdio: 'ignore', detached: true });
    child.on('error', () => {});
    child.unref();
  } catch {
    // no browser opener: the printed URL is enough
  }
}
