// The formulas the Section 3.1 and 3.2 gadget tests enumerate.

/** Every formula over x, y, z with one to three clauses of one or two literals. */
export function smallFormulas(): string[] {
  const literals = ['x', '!x', 'y', '!y', 'z', '!z'];
  const clauses: string[] = [...literals];
  for (let a = 0; a < 6; a++) for (let b = a + 1; b < 6; b++) if (a >> 1 !== b >> 1) clauses.push(`${literals[a]} | ${literals[b]}`);
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
