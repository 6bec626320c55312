import type { RegionExplanation } from 'hodt';

/** The regions of order k as every part of the page counts and words them: a
 * region has a choice when it has two or more k-OD triangulations, and a count
 * the library did not finish is a lower bound ("at least"). The library never
 * reports an unfinished region of two or more triangles as fewer than two. */
export interface RegionCount {
  regions: number;
  withChoice: number;
  /** The most triangulations in one region, and whether that count is exact. */
  most: number;
  mostExact: boolean;
}

/** Does region g have two or more triangulations (or a count not finished)? */
export function hasChoice(r: RegionExplanation, g: number): boolean {
  return r.triangulations[g]! >= 2 || r.complete[g] !== 1;
}

export function countRegions(r: RegionExplanation): RegionCount {
  let withChoice = 0, most = 0, mostExact = true;
  r.triangulations.forEach((c, i) => {
    const exact = r.complete[i] === 1;
    if (hasChoice(r, i)) withChoice++;
    // The largest count; on a tie an unfinished one wins (it may be more).
    if (c > most) (most = c), (mostExact = exact);
    else if (c === most && !exact) mostExact = false;
  });
  return { regions: r.triangulations.length, withChoice, most, mostExact };
}

/** One region's count as the page shows it: "12", or "at least 2". */
export function triangulationsLabel(count: number, complete: boolean): string {
  return complete ? String(count) : `at least ${count}`;
}

/** The same, short enough to print inside a region of the plan: "12", "≥2". */
export function triangulationsMark(count: number, complete: boolean): string {
  return complete ? String(count) : `≥${count}`;
}

/** "70 regions with a choice (the most triangulations in one: at least 40)". */
export function describeRegions(c: RegionCount): string {
  const head = `${c.withChoice.toLocaleString('en')} region${c.withChoice === 1 ? '' : 's'} with a choice`;
  return c.withChoice === 0 ? head : `${head} (the most triangulations in one: ${triangulationsLabel(c.most, c.mostExact)})`;
}

/** The solver's own summary of the regions leads its details at order k (it
 * counts the regions where the objective can tell triangulations apart, which
 * is not the page's count): the rest of the details, without it. */
export function detailsWithoutRegionSummary(details: string): string {
  return details.replace(/^\d+ regions with a choice \([^)]*\)(; )?/, '');
}
