/** Boolean formulas for the hardness gadgets: parsing, evaluation, brute force. */
export interface Literal {
  variable: number;
  negated: boolean;
}
export type Clause = [Literal, Literal];
export interface Formula {
  /** Variable names in order of first appearance. */
  names: string[];
  clauses: Clause[];
}

export const MAX_VARIABLES = 10;
export const MAX_CLAUSES = 12;

export class FormulaError extends Error {
  override name = 'FormulaError';
}

/** Clauses of any number of literals (the Section 3.1 and 3.2 gadgets take 3-SAT). */
export interface Cnf {
  names: string[];
  clauses: Literal[][];
}

/**
 * Reads clauses like "x1 | x2, !x1 | x3; (~x2 or x3)": clauses are separated by
 * commas, semicolons, newlines, & or ∧; literals by |, ∨ or "or"; a negation is
 * !, ~, ¬, - or "not". Every clause has `minLiterals` to `maxLiterals` literals on
 * different variables.
 */
export function parseCnf(text: string, minLiterals: number, maxLiterals: number, example: string): Cnf {
  const names: string[] = [];
  const clauses: Literal[][] = [];
  const parts = text
    .split(/[,;\n&∧]+/)
    .map((c) => c.trim().replace(/^\(+|\)+$/g, '').trim())
    .filter((c) => c !== '');
  if (parts.length === 0) throw new FormulaError(`type at least one clause, for example "${example}"`);
  const count = (k: number) => ['no', 'one', 'two', 'three'][k] ?? String(k);
  const wanted = minLiterals === maxLiterals ? `${count(minLiterals)} literals` : `${count(minLiterals)} ${maxLiterals === minLiterals + 1 ? 'or' : 'to'} ${count(maxLiterals)} literals`;
  for (const part of parts) {
    const literals = part.split(/\s*(?:\|\|?|∨|\bor\b)\s*/i).filter((l) => l.trim() !== '');
    if (literals.length < minLiterals || literals.length > maxLiterals) throw new FormulaError(`"${part}" should have ${wanted} joined by |`);
    const parsed = literals.map((raw) => {
      const m = /^\s*((?:[!~¬-]|not\s+)*)\s*([A-Za-z_][A-Za-z0-9_]*)\s*$/i.exec(raw);
      if (!m) throw new FormulaError(`"${raw.trim()}" is not a literal (a variable name, maybe with ! before it)`);
      const negations = (m[1]!.match(/[!~¬-]|not/gi) ?? []).length;
      const name = m[2]!;
      let variable = names.indexOf(name);
      if (variable < 0) {
        names.push(name);
        variable = names.length - 1;
      }
      return { variable, negated: negations % 2 === 1 };
    });
    const seen = new Set<number>();
    for (const l of parsed) {
      if (seen.has(l.variable)) throw new FormulaError(`"${part}" uses ${names[l.variable]} twice: each clause needs different variables`);
      seen.add(l.variable);
    }
    clauses.push(parsed);
  }
  return { names, clauses };
}

/** A MAX-2-SAT formula for the Section 3.3 gadget: every clause has two literals. */
export function parseFormula(text: string): Formula {
  const { names, clauses } = parseCnf(text, 2, 2, 'x1 | x2, !x1 | x3');
  if (names.length > MAX_VARIABLES) throw new FormulaError(`${names.length} variables: the gadget takes at most ${MAX_VARIABLES}`);
  if (clauses.length > MAX_CLAUSES) throw new FormulaError(`${clauses.length} clauses: the gadget takes at most ${MAX_CLAUSES}`);
  return { names, clauses: clauses as Clause[] };
}

export function formatLiteral(f: Formula, l: Literal): string {
  return `${l.negated ? '¬' : ''}${f.names[l.variable]}`;
}
export function formatClause(f: Formula, c: Clause): string {
  return `${formatLiteral(f, c[0])} ∨ ${formatLiteral(f, c[1])}`;
}

export const literalTrue = (l: Literal, assignment: readonly boolean[]) => assignment[l.variable] !== l.negated;
export const clauseTrue = (c: Clause, assignment: readonly boolean[]) => literalTrue(c[0], assignment) || literalTrue(c[1], assignment);

export function countSatisfied(f: Formula, assignment: readonly boolean[]): number {
  return f.clauses.filter((c) => clauseTrue(c, assignment)).length;
}

/** The MAX-2-SAT optimum by trying all 2^n assignments, and how many reach it. */
export function maxSatisfiable(f: Formula): { best: number; count: number; example: boolean[] } {
  const n = f.names.length;
  let best = -1, count = 0;
  let example: boolean[] = [];
  for (let mask = 0; mask < 1 << n; mask++) {
    const a = Array.from({ length: n }, (_, v) => ((mask >> v) & 1) === 1);
    const k = countSatisfied(f, a);
    if (k > best) (best = k), (count = 1), (example = a);
    else if (k === best) count++;
  }
  return { best, count, example };
}

/** Is some assignment satisfying every clause? Tries all 2^n; returns one or null. */
export function satisfyingAssignment(f: Cnf): boolean[] | null {
  const n = f.names.length;
  for (let mask = 0; mask < 1 << n; mask++) {
    const a = Array.from({ length: n }, (_, v) => ((mask >> v) & 1) === 1);
    if (f.clauses.every((c) => c.some((l) => literalTrue(l, a)))) return a;
  }
  return null;
}
