/** Drops every point whose (x, y) equals an earlier point's (as the library's
 * dedupe "first" does), keeping the order of the rest. */
export function dropDuplicateXY(xyz: Float64Array): { points: Float64Array; removed: number } {
  const seen = new Set<string>();
  const keep: number[] = [];
  for (let i = 0; i < xyz.length; i += 3) {
    // x + 0 turns -0 into 0: the two are the same position.
    const key = `${xyz[i]! + 0},${xyz[i + 1]! + 0}`;
    if (seen.has(key)) continue;
    seen.add(key);
    keep.push(xyz[i]!, xyz[i + 1]!, xyz[i + 2]!);
  }
  return { points: Float64Array.from(keep), removed: (xyz.length - keep.length) / 3 };
}
