// `hodt demo`'s options, run as users run it: `node dist/cli.js demo ...`.
import { spawnSync } from 'node:child_process';
import { describe, expect, it } from 'vitest';

const root = new URL('../../', import.meta.url).pathname;
const demo = (...args: string[]) => {
  const r = spawnSync('node', [`${root}dist/cli.js`, 'demo', ...args], { encoding: 'utf8', timeout: 30_000 });
  return { code: r.status, out: r.stdout, err: r.stderr };
};

describe('hodt demo', () => {
  it('--help prints every option and serves nothing', () => {
    for (const flag of ['--help', '-h']) {
      const r = demo(flag);
      expect(r.code).toBe(0);
      expect(r.err).toBe('');
      for (const option of ['--port N', '--no-open', '--help']) expect(r.out).toContain(option);
      expect(r.out).not.toContain('unknown option');
    }
  });
  it('an unknown option is one line with the usage, exit 2', () => {
    const r = demo('--bogus');
    expect(r.code).toBe(2);
    expect(r.err).toBe("hodt demo: unknown option '--bogus'; usage: hodt demo [--port N] [--no-open] [--help]\n");
  });
});
