import type { Method } from 'hodt';

/** Solver methods offered in the demo, auto first. */
export const METHODS: readonly Method[] = ['auto', 'exact', 'approx', 'brute-force'];

/** Orders k of the Delaunay triangulations the demo offers (1 = first order). */
export const MAX_ORDER = 8;
export const isOrder = (k: unknown): k is number => typeof k === 'number' && Number.isInteger(k) && k >= 1 && k <= MAX_ORDER;

/** How the views share the page: both side by side, or one of them. */
export const VIEW_MODES = ['split', '3d', 'plan', 'teach'] as const;
export type ViewMode = (typeof VIEW_MODES)[number];
