import type { Method } from 'hodt';

/** Solver methods offered in the demo, auto first. */
export const METHODS: readonly Method[] = ['auto', 'exact', 'approx', 'brute-force'];

/** How the views share the page: both side by side, or one of them. */
export const VIEW_MODES = ['split', '3d', 'plan'] as const;
export type ViewMode = (typeof VIEW_MODES)[number];
