import type { ObjectiveId } from 'hodt';

/** What each objective means, for students: a short name, a label for the
 * measures table, one or two sentences, and the unit of its value. */
export interface ObjectiveHelp {
  name: string;
  /** Short label of the measure (measures table). */
  measure: string;
  help: string;
  /** 'angle' values are radians, shown in degrees. */
  unit: 'count' | 'ratio' | 'angle' | 'length' | 'area' | 'degree';
  /** NP-hard objectives: exact only while the problem decomposes, else approximated. */
  hard?: boolean;
}

export const OBJECTIVE_HELP: Record<ObjectiveId, ObjectiveHelp> = {
  'max-convex-vertices': {
    name: 'Most convex vertices',
    measure: 'Convex vertices',
    help: 'A vertex is convex when the surface around it bulges upward, like a hilltop: a plane through it has all its neighbours on or below. More convex vertices make a rounder, more natural surface.',
    unit: 'count',
  },
  'minmax-edge-area-ratio': {
    name: 'Similar neighbouring triangles',
    measure: 'Worst edge area ratio',
    help: 'For two triangles sharing an edge, divide the larger area by the smaller. This keeps the worst such ratio as small as possible, so neighbouring triangles have similar sizes.',
    unit: 'ratio',
  },
  'minmax-edge-normal-angle': {
    name: 'Gentlest folds',
    measure: 'Worst edge normal angle',
    help: 'Where two triangles meet along an edge, the surface folds by the angle between their normals. This makes the sharpest fold as gentle as possible.',
    unit: 'angle',
  },
  'minmax-edge-enclosing-circle': {
    name: 'Compact neighbouring triangles',
    measure: 'Worst enclosing circle',
    help: 'Take the smallest circle around each pair of triangles sharing an edge. This keeps the largest such circle small, so no pair spreads out far.',
    unit: 'length',
  },
  'minmax-vertex-area-ratio': {
    name: 'Similar triangles around a point',
    measure: 'Worst vertex area ratio',
    help: 'Like the edge area ratio, but every two triangles sharing a corner count: the sizes must match all around each point.',
    unit: 'ratio',
  },
  'minmax-vertex-normal-angle': {
    name: 'Gentlest bends around a point',
    measure: 'Worst vertex normal angle',
    help: 'Like the edge normal angle, but compares every two triangles sharing a corner: limits how much the surface bends around each point.',
    unit: 'angle',
  },
  'min-local-minima': {
    name: 'Fewest pits',
    measure: 'Local minima',
    help: 'A local minimum (▼) is a point lower than all its neighbours: a pit where water would pool. Real terrains have few; a careless triangulation creates fake ones. This removes as many as possible.',
    unit: 'count',
  },
  'min-local-extrema': {
    name: 'Fewest pits and peaks',
    measure: 'Local extrema',
    help: 'Counts the pits (▼) and the peaks (▲, points higher than all their neighbours) together and makes as few of them as possible.',
    unit: 'count',
  },
  'min-total-edge-length': {
    name: 'Shortest edges',
    measure: 'Total edge length',
    help: 'Makes the total length of all edges, measured on the map, as small as possible: in each flippable quad the shorter diagonal wins.',
    unit: 'length',
  },
  'minmax-triangle-area': {
    name: 'Smallest largest triangle',
    measure: 'Largest triangle area',
    help: 'Makes the biggest triangle (area on the map) as small as possible, so no part of the terrain is covered by one coarse triangle.',
    unit: 'area',
  },
  'max-convex-edges': {
    name: 'Most ridge edges',
    measure: 'Convex edges',
    help: 'An edge is convex when the surface bends down on both sides of it, like a ridge (red); reflex edges are valleys (blue). This makes as many edges convex as possible. NP-hard: exact while the quads interact little, otherwise approximated with a proven bound.',
    unit: 'count',
    hard: true,
  },
  'min-mixed-vertices': {
    name: 'Fewest saddle-like points',
    measure: 'Mixed vertices',
    help: 'A mixed vertex (purple) is neither convex, concave nor flat: around it the surface goes up and down like a saddle. Fewer of them means a cleaner surface. NP-hard: exact or approximated with a bound.',
    unit: 'count',
    hard: true,
  },
  'minmax-degree': {
    name: 'Lowest maximum degree',
    measure: 'Maximum degree',
    help: 'The degree of a point is the number of edges meeting there. This makes the largest degree as small as possible, avoiding fans of many thin triangles. NP-hard: exact or approximated with a bound.',
    unit: 'degree',
  },
};

/** A value for display: counts as integers, angles in degrees, others with 4
 * significant digits. */
export function formatValue(id: ObjectiveId, v: number | null): string {
  if (v === null || !Number.isFinite(v)) return '—';
  const unit = OBJECTIVE_HELP[id].unit;
  if (unit === 'count' || unit === 'degree') return Number.isInteger(v) ? v.toLocaleString('en') : v.toFixed(2);
  if (unit === 'angle') return `${((v * 180) / Math.PI).toFixed(2)}°`;
  return significant(v);
}

export function significant(v: number, digits = 4): string {
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e6 || a < 1e-3) return v.toExponential(digits - 1);
  return Number(v.toPrecision(digits)).toLocaleString('en', { maximumFractionDigits: 6 });
}
