/**
 * 2-SAT over quads (Aspvall, Plass and Tarjan; paper, Section 2.1): literal 2q + x
 * says "quad q takes state x" (0 Delaunay diagonal, 1 flipped). A clause is a pair
 * of literals of which at least one must hold; a unit clause repeats its literal.
 * Satisfiable iff no quad has both of its literals in one strongly connected
 * component of the implication graph.
 */
export interface TwoSatResult {
  satisfiable: boolean;
  /** Per quad: its state in a satisfying assignment (null if unsatisfiable). */
  assignment: Uint8Array | null;
  /** Per literal: its strongly connected component (Tarjan's numbering, which is
   * a reverse topological order). */
  component: Int32Array;
  /** Size of each component. */
  componentSize: Int32Array;
  /** Quads whose two literals share a component (the contradictions). */
  conflicts: number[];
}

export function solveTwoSat(numVars: number, clauses: readonly (readonly [number, number])[]): TwoSatResult {
  const n = 2 * numVars;
  // Implications: not a -> b and not b -> a, as adjacency lists (CSR).
  const degree = new Int32Array(n + 1);
  for (const [a, b] of clauses) {
    degree[(a ^ 1) + 1]!++;
    degree[(b ^ 1) + 1]!++;
  }
  for (let i = 0; i < n; i++) degree[i + 1]! += degree[i]!;
  const next = new Int32Array(degree[n]!);
  const fill = degree.slice(0, n);
  for (const [a, b] of clauses) {
    next[fill[a ^ 1]!++] = b;
    next[fill[b ^ 1]!++] = a;
  }
  // Tarjan, iteratively.
  const index = new Int32Array(n).fill(-1);
  const low = new Int32Array(n);
  const component = new Int32Array(n).fill(-1);
  const onStack = new Uint8Array(n);
  const stack: number[] = [];
  const sizes: number[] = [];
  let counter = 0;
  const work: [number, number][] = [];
  for (let s = 0; s < n; s++) {
    if (index[s]! >= 0) continue;
    work.push([s, degree[s]!]);
    index[s] = low[s] = counter++;
    stack.push(s);
    onStack[s] = 1;
    while (work.length) {
      const top = work[work.length - 1]!;
      const v = top[0];
      if (top[1] < degree[v + 1]!) {
        const w = next[top[1]++]!;
        if (index[w]! < 0) {
          index[w] = low[w] = counter++;
          stack.push(w);
          onStack[w] = 1;
          work.push([w, degree[w]!]);
        } else if (onStack[w]) {
          low[v] = Math.min(low[v]!, index[w]!);
        }
        continue;
      }
      work.pop();
      if (work.length) {
        const u = work[work.length - 1]![0];
        low[u] = Math.min(low[u]!, low[v]!);
      }
      if (low[v] === index[v]) {
        const id = sizes.length;
        let size = 0;
        let w: number;
        do {
          w = stack.pop()!;
          onStack[w] = 0;
          component[w] = id;
          size++;
        } while (w !== v);
        sizes.push(size);
      }
    }
  }
  const conflicts: number[] = [];
  for (let q = 0; q < numVars; q++) if (component[2 * q] === component[2 * q + 1]) conflicts.push(q);
  let assignment: Uint8Array | null = null;
  if (conflicts.length === 0) {
    assignment = new Uint8Array(numVars);
    // A literal holds if its component comes later in topological order, that is
    // earlier in Tarjan's numbering.
    for (let q = 0; q < numVars; q++) assignment[q] = component[2 * q + 1]! < component[2 * q]! ? 1 : 0;
  }
  return { satisfiable: conflicts.length === 0, assignment, component, componentSize: Int32Array.from(sizes), conflicts };
}
