// Reading a triangulation of the Section 3.1 gadget back as an assignment, and the
// per-instance check that the construction behaves as the proof says.
import { literalTrue, type Cnf } from '../formula.ts';
import { sectorCorners, type MixedGadget } from './build.ts';

/** Which library quad each fan sector is, and whether its Delaunay diagonal is
 * the counterclockwise one. */
export interface FanSectors {
  /** Per fan, per sector: the quad. */
  quad: Int32Array[];
  delaunayCcw: Uint8Array[];
  /** Flippable quads of the terrain that are not sectors (inside a fan's inner
   * ring or in the filling between fans). */
  otherQuads: number;
}

export function mapFanSectors(g: MixedGadget, quads: Uint32Array): FanSectors {
  const byCorners = new Map<string, number>();
  const key = (a: ArrayLike<number>) => Array.from(a).sort((x, y) => x - y).join(',');
  for (let q = 0; q < quads.length / 4; q++) byCorners.set(key(quads.subarray(4 * q, 4 * q + 4)), q);
  const quad: Int32Array[] = [], delaunayCcw: Uint8Array[] = [];
  for (const fan of g.fans) {
    const qs = new Int32Array(fan.inner.length), ccw = new Uint8Array(fan.inner.length);
    fan.inner.forEach((_, k) => {
      const corners = sectorCorners(fan, k);
      const q = byCorners.get(key(corners));
      if (q === undefined) throw new Error(`sector ${k} of the fan of ${g.formula.names[fan.variable]} is not a flippable quad of the terrain`);
      qs[k] = q;
      const a = quads[4 * q]!, b = quads[4 * q + 1]!;
      ccw[k] = (a === corners[0] && b === corners[2]) || (a === corners[2] && b === corners[0]) ? 1 : 0;
    });
    quad.push(qs);
    delaunayCcw.push(ccw);
  }
  return { quad, delaunayCcw, otherQuads: quads.length / 4 - g.fans.reduce((s, fan) => s + fan.inner.length, 0) };
}

/** The triangulation of an assignment: every sector of a fan counterclockwise
 * when its variable's value is the fan's counterclockwise value; the quads that
 * are not sectors as in `base` (Delaunay when not given). */
export function mixedChoice(g: MixedGadget, map: FanSectors, assignment: readonly boolean[], numQuads: number, base?: Uint8Array): Uint8Array {
  const choice = base ? Uint8Array.from(base) : new Uint8Array(numQuads);
  g.fans.forEach((fan, i) => {
    const ccw = assignment[fan.variable] === fan.ccwIsTrue;
    map.quad[i]!.forEach((q, k) => (choice[q] = ccw === (map.delaunayCcw[i]![k] === 1) ? 0 : 1));
  });
  return choice;
}

/** Per fan: the value most of its sectors say, and how many sectors disagree
 * (a fan in a pure state has none). */
export function readMixedAssignment(g: MixedGadget, map: FanSectors, choice: Uint8Array): { assignment: boolean[]; disagreeing: number[] } {
  const n = g.formula.names.length;
  const assignment = new Array<boolean>(n).fill(false);
  const disagreeing = new Array<number>(n).fill(0);
  g.fans.forEach((fan, i) => {
    const ccw = Array.from(map.quad[i]!, (q, k) => (choice[q] === 0) === (map.delaunayCcw[i]![k] === 1));
    const up = ccw.filter(Boolean).length;
    assignment[fan.variable] = up * 2 >= ccw.length ? fan.ccwIsTrue : !fan.ccwIsTrue;
    disagreeing[fan.variable] = Math.min(up, ccw.length - up);
  });
  return { assignment, disagreeing };
}

export const unsatisfiedClauses = (f: Cnf, a: readonly boolean[]) => f.clauses.filter((c) => !c.some((l) => literalTrue(l, a))).length;

export interface MixedCertificate {
  /** Per assignment (bit v of the index = variable v): mixed vertices of its triangulation. */
  values: number[];
  /** Assignments whose triangulation does not have floor + (its false clauses) mixed vertices. */
  wrong: number[];
}

/** Mixed vertices of every assignment's triangulation, against floor + its
 * false clauses (what the proof says each costs). */
export function certifyMixed(g: MixedGadget, map: FanSectors, numQuads: number, mixed: (choice: Uint8Array) => number, base?: Uint8Array): MixedCertificate {
  const n = g.formula.names.length;
  const values: number[] = [];
  const wrong: number[] = [];
  for (let mask = 0; mask < 1 << n; mask++) {
    const a = Array.from({ length: n }, (_, v) => ((mask >> v) & 1) === 1);
    const value = mixed(mixedChoice(g, map, a, numQuads, base));
    values.push(value);
    if (value !== g.floor + unsatisfiedClauses(g.formula, a)) wrong.push(mask);
  }
  return { values, wrong };
}
