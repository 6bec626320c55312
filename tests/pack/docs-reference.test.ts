// The README and the docs read as reference: what the code does, not when it
// changed. Dates belong in CHANGELOG.md (and measurements' history with them),
// so a dated line in a reference doc fails here.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { datesIn } from './markdown.js';
import { repo } from './project.js';

const docs = ['README.md', ...readdirSync(join(repo, 'docs')).filter((f) => f.endsWith('.md')).map((f) => `docs/${f}`), 'web/demo/README.md'];

describe('reference docs', () => {
  it('datesIn finds ISO and month-name dates, and nothing else', () => {
    const found = datesIn('built 2026-11-23\non 2026/12/01, November 23, Nov. 5th\n23 November and Dec 2026\n').map((d) => d.date);
    expect(found).toEqual(['2026-11-23', '2026/12/01', 'November 23', 'Nov. 5th', '23 November', 'Dec 2026']);
    expect(datesIn('k = 2026, 1000 x 1000, 12-16 points, 0.23-0.43, may 5 be, March of time, ESRI 33N').map((d) => d.date)).toEqual([]);
  });

  it.each(docs)('%s has no dates (the record is CHANGELOG.md)', (doc) => {
    const text = readFileSync(join(repo, doc), 'utf8');
    expect(datesIn(text).map((d) => `${doc}:${d.line}: ${d.date}`)).toEqual([]);
    expect(text).not.toMatch(/\bthis session\b|\bsession of\b/i);
  });

  it('the changelog holds the dated record, newest first', () => {
    const dates = [...readFileSync(join(repo, 'CHANGELOG.md'), 'utf8').matchAll(/^## (\d{4}-\d{2}-\d{2})$/gm)].map((m) => m[1]!);
    expect(dates.length).toBeGreaterThan(0);
    expect(dates).toEqual([...dates].sort().reverse());
  });
});
