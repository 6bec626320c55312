// The formulas the Section 3.1 and 3.2 gadget tests enumerate.

/** Every formula over x, y, z with one to three clauses of one to `maxLiterals`
 * (2 or 3) literals on different variables. */
export function smallFormulas(maxLiterals = 2): string[] {
  const literals = ['x', '!x', 'y', '!y', 'z', '!z'];
  const clauses: string[] = [...literals];
  for (let a = 0; a < 6; a++) for (let b = a + 1; b < 6; b++) if (a >> 1 !== b >> 1) clauses.push(`${literals[a]} | ${literals[b]}`);
  if (maxLiterals >= 3) for (const p of ['x', '!x']) for (const q of ['y', '!y']) for (const r of ['z', '!z']) clauses.push(`${p} | ${q} | ${r}`);
  const out: string[] = [];
  for (let i = 0; i < clauses.length; i++) {
    out.push(clauses[i]!);
    for (let j = i; j < clauses.length; j++) {
      out.push(`${clauses[i]}, ${clauses[j]}`);
      for (let k = j; k < clauses.length; k++) out.push(`${clauses[i]}, ${clauses[j]}, ${clauses[k]}`);
    }
  }
  return out;
}

/** A fixed pseudo-random sample of `count` formulas over four to six variables
 * (a to f), two to six clauses, most of three literals. */
export function randomFormulas(count: number, seed = 7): string[] {
  let s = seed;
  // A linear congruential generator; its high bits, since the low ones cycle fast.
  const next = (k: number) => ((s = (Math.imul(s, 1103515245) + 12345) & 0x7fffffff), (s >>> 16) % k);
  const out: string[] = [];
  for (let i = 0; i < count; i++) {
    const variables = 4 + next(3);
    const clauses: string[] = [];
    for (let c = 2 + next(5); c > 0; c--) {
      const size = next(3) === 0 ? 1 + next(2) : 3;
      const vs = new Set<number>();
      while (vs.size < size) vs.add(next(variables));
      clauses.push([...vs].map((v) => (next(2) ? '!' : '') + 'abcdef'[v]).join(' | '));
    }
    out.push(clauses.join(', '));
  }
  return out;
}
