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
