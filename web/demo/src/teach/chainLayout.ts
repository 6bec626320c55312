// The layout of the Section 3.2 gadget: a formula of one- and two-literal clauses
// read as chains of variables, each two-literal clause a joint between two
// neighbours of a chain. A formula whose clause graph is not a set of paths (a
// variable in three clauses, a cycle, a three-literal clause) is refused with the
// reason, since the gadget lays its chains out along one line. (The Section 3.1
// gadget places its fans on a hexagonal grid instead: mixed/build.ts.)
import type { Cnf, Literal } from './formula.ts';

export class ChainLayoutError extends Error {
  override name = 'ChainLayoutError';
}

export const clauseText = (f: Cnf, c: Literal[]) => c.map((l) => (l.negated ? '¬' : '') + f.names[l.variable]).join(' ∨ ');

export interface Occurrence {
  clause: number;
  literal: Literal;
}

/** Chains of variables joined by two-literal clauses, or a message saying why the
 * formula cannot be laid out with straight wires. */
export function chainLayout(f: Cnf): { chains: number[][]; joints: Map<string, number[]>; units: Occurrence[][] } {
  const n = f.names.length;
  const occurrences: Occurrence[][] = Array.from({ length: n }, () => []);
  f.clauses.forEach((c, k) => c.forEach((literal) => occurrences[literal.variable]!.push({ clause: k, literal })));
  f.clauses.forEach((c) => {
    if (c.length > 2) throw new ChainLayoutError(`"${clauseText(f, c)}" has three literals: this page lays out clauses of one or two literals only (see the note below)`);
  });
  occurrences.forEach((o, v) => {
    if (o.length > 2) throw new ChainLayoutError(`${f.names[v]} is in ${o.length} clauses: a chain has two ends, so each variable may be in at most two`);
  });
  const neighbours: number[][] = Array.from({ length: n }, () => []);
  const joints = new Map<string, number[]>();
  f.clauses.forEach((c, k) => {
    if (c.length !== 2) return;
    const [a, b] = [c[0]!.variable, c[1]!.variable];
    const shared = joints.get(`${a},${b}`);
    if (shared) {
      // A second clause on the same two variables fits on the joint's other corner.
      if (shared.length > 1) throw new ChainLayoutError(`${f.names[a]} and ${f.names[b]} share three clauses: a joint has two corners`);
      shared.push(k);
      return;
    }
    neighbours[a]!.push(b);
    neighbours[b]!.push(a);
    const list = [k];
    joints.set(`${a},${b}`, list);
    joints.set(`${b},${a}`, list);
  });
  const units = occurrences.map((o) => o.filter((x) => f.clauses[x.clause]!.length === 1));
  const seen = new Uint8Array(n);
  const chains: number[][] = [];
  for (let s = 0; s < n; s++) {
    if (seen[s] || neighbours[s]!.length > 1) continue;
    const chain = [s];
    seen[s] = 1;
    let prev = -1, cur = s;
    for (;;) {
      const next = neighbours[cur]!.find((w) => w !== prev);
      if (next === undefined) break;
      chain.push(next);
      seen[next] = 1;
      prev = cur;
      cur = next;
    }
    chains.push(chain);
  }
  const left = [...seen].findIndex((x) => x === 0);
  if (left >= 0) throw new ChainLayoutError(`the clauses through ${f.names[left]} form a cycle: the gadget is laid out along a line, so this page takes chains only`);
  return { chains, joints, units };
}
