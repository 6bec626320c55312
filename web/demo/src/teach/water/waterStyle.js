// @ts-check
// How water is drawn, in the demo's Water view and in the README's drainage
// figure (scripts/drainage-figure.mjs, which runs this in Node without a build:
// hence plain JavaScript with its types in JSDoc): the colours, the width of a
// flow line, and which basin colours which triangle.
//
// The Delaunay basins are coloured so that basins side by side differ; every
// other triangulation's basin takes the colour of the Delaunay basin its pit or
// outlet lies in. A basin that the optimum merges into a neighbour therefore
// shows in the neighbour's colour, and a basin that stays keeps its own.

export const FLOW_COLOR = '#0b4f8a';
export const PIT_COLOR = '#c62828';
export const OUTLET_COLOR = '#1565c0';
/** The opacity of a basin's fill over white. */
export const BASIN_OPACITY = 0.4;
/** A triangle whose three corners drain to three different places. */
export const NO_BASIN_COLOR = '#f1f3f2';

/** Basin fills: categorical, without red (pits are red) or grey (no basin). */
export const BASIN_COLORS = /** @type {const} */ (['#1f77b4', '#2ca02c', '#ff7f0e', '#9467bd', '#17becf', '#bcbd22', '#8c564b', '#e377c2']);

/**
 * a[i], for an index the caller knows is in range.
 * @param {ArrayLike<number>} a
 * @param {number} i
 * @returns {number}
 */
const at = (a, i) => /** @type {number} */ (a[i]);

/**
 * The basin (the pit or outlet) that at least two of triangle t's corners drain
 * to, or -1 if the three differ.
 * @param {ArrayLike<number>} triangles point indices, three per triangle
 * @param {ArrayLike<number>} basin per point, its pit or outlet
 * @param {number} t
 * @returns {number}
 */
export function majorityBasin(triangles, basin, t) {
  const a = at(basin, at(triangles, 3 * t)), b = at(basin, at(triangles, 3 * t + 1)), c = at(basin, at(triangles, 3 * t + 2));
  return a === b || a === c ? a : b === c ? b : -1;
}

/**
 * Colour slots (0 to count - 1) per point: the slot of the Delaunay basin the
 * point lies in (-1 for a point in none, a dropped duplicate). Basins are
 * coloured greedily, largest first, each with a slot none of its neighbours
 * (basins joined by an edge of the triangulation) took, the one fewest basins
 * took so far (so that every colour is used); with every slot taken by a
 * neighbour, the one fewest neighbours share.
 *
 * The colour of the basin of pit or outlet r, in any triangulation of the same
 * points, is `slots[r]`.
 * @param {ArrayLike<number>} triangles the Delaunay triangulation
 * @param {ArrayLike<number>} basin its drainage's basin per point
 * @param {number} count how many slots there are
 * @returns {Int32Array}
 */
export function basinSlots(triangles, basin, count) {
  /** @type {Map<number, Set<number>>} */
  const next = new Map();
  /** @type {Map<number, number>} */
  const size = new Map();
  for (let v = 0; v < basin.length; v++) {
    const r = at(basin, v);
    if (r < 0) continue;
    size.set(r, (size.get(r) ?? 0) + 1);
    if (!next.has(r)) next.set(r, new Set());
  }
  for (let k = 0; k < triangles.length; k++) {
    const r = at(basin, at(triangles, k)), s = at(basin, at(triangles, k - (k % 3) + ((k % 3) + 1) % 3));
    if (r >= 0 && s >= 0 && r !== s) next.get(r)?.add(s), next.get(s)?.add(r);
  }
  const order = [...size.keys()].sort((r, s) => (size.get(s) ?? 0) - (size.get(r) ?? 0) || r - s);
  /** @type {Map<number, number>} */
  const slotOf = new Map();
  const taken = new Array(count).fill(0);
  for (const r of order) {
    const shared = new Array(count).fill(0);
    for (const s of next.get(r) ?? []) {
      const slot = slotOf.get(s);
      if (slot !== undefined) shared[slot]++;
    }
    let best = 0;
    for (let slot = 1; slot < count; slot++) if (shared[slot] < shared[best] || (shared[slot] === shared[best] && taken[slot] < taken[best])) best = slot;
    slotOf.set(r, best);
    taken[best]++;
  }
  return Int32Array.from(Array.from(basin, (r) => (r < 0 ? -1 : (slotOf.get(r) ?? -1))));
}

/**
 * Line width of a flow segment: grows with log(accumulation), 1 for a point
 * that drains only itself, `widest` for the largest flow.
 * @param {number} accumulation
 * @param {number} maxAccumulation
 * @returns {number}
 */
export function flowWidth(accumulation, maxAccumulation, widest = 6) {
  if (maxAccumulation <= 1) return 1;
  return 1 + ((widest - 1) * Math.log(accumulation)) / Math.log(maxAccumulation);
}
