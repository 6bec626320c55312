// What the package tests read in its Markdown: fenced code blocks, link targets
// (outside code) and the anchors GitHub and npm give headings.

export interface CodeBlock {
  lang: string;
  code: string;
}

/** The fenced code blocks, in order, with their info string's first word. */
export function codeBlocks(markdown: string): CodeBlock[] {
  return [...markdown.matchAll(/^```(\S*)[^\n]*\n([\s\S]*?)^```$/gm)].map((m) => ({ lang: m[1]!, code: m[2]! }));
}

// The text without fenced blocks and inline code spans (a `[a](b)` there is code).
function prose(markdown: string): string {
  return markdown.replace(/^```[\s\S]*?^```$/gm, '').replace(/`[^`\n]*`/g, '');
}

/** Targets of inline links and images, [text](target) and ![alt](target). */
export function linkTargets(markdown: string): string[] {
  return [...prose(markdown).matchAll(/!?\[[^\]]*\]\(([^)\s]*)(?:\s+"[^"]*")?\)/g)].map((m) => m[1]!);
}

/** The anchors of the headings, as GitHub makes them: lower case, punctuation
 * dropped, spaces as hyphens, "-1", "-2" for repeats. */
export function headingAnchors(markdown: string): Set<string> {
  const anchors = new Set<string>();
  for (const m of markdown.replace(/^```[\s\S]*?^```$/gm, '').matchAll(/^#{1,6}\s+(.+?)\s*#*$/gm)) {
    const base = m[1]!.toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, '').replace(/\s/g, '-');
    let anchor = base;
    for (let n = 1; anchors.has(anchor); ++n) anchor = `${base}-${n}`;
    anchors.add(anchor);
  }
  return anchors;
}

const MONTH = '(?:Jan(?:uary)?|Feb(?:ruary)?|Mar(?:ch)?|Apr(?:il)?|May|June?|July?|Aug(?:ust)?|Sep(?:t(?:ember)?)?|Oct(?:ober)?|Nov(?:ember)?|Dec(?:ember)?)';
// 2026-11-23, 2026/11/23; November 23, Nov. 23rd; 23 November; November 2026.
const DATE = new RegExp(
  [
    String.raw`\b\d{4}[-/](?:0[1-9]|1[0-2])[-/](?:0[1-9]|[12]\d|3[01])\b`,
    String.raw`\b${MONTH}\.?\s+\d{1,2}(?:st|nd|rd|th)?\b`,
    String.raw`\b\d{1,2}(?:st|nd|rd|th)?\s+${MONTH}\b`,
    String.raw`\b${MONTH}\.?\s+\d{4}\b`,
  ].join('|'),
  'g',
);

/** The dates written in a text (ISO or with a month's name), each with its line
 * number: reference docs describe the code as it is, and the dated record is the
 * changelog's. */
export function datesIn(text: string): { line: number; date: string }[] {
  return text.split('\n').flatMap((l, i) => [...l.matchAll(DATE)].map((m) => ({ line: i + 1, date: m[0] })));
}
