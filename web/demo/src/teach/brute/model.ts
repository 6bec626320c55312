// The model of the "All triangulations" view: every first order triangulation
// of a small terrain (2^m choices, from terrain.enumerateAll()) ranked by the
// sidebar's objective, best first.
import { OBJECTIVE_IDS, type ObjectiveId, type Terrain } from 'hodt';
import { readStructure, type QuadStructure } from '../structure.ts';

/** Up to 2^10 = 1024 thumbnails. */
export const MAX_BRUTE_QUADS = 10;

/** A choice of diagonals as a bit mask (bit q: quad q flipped), and its value. */
export interface Ranked {
  mask: number;
  value: number;
}

export interface BruteModel {
  terrain: Terrain;
  structure: QuadStructure;
  objective: ObjectiveId;
  sense: 'min' | 'max';
  /** Every choice, best first. */
  order: Ranked[];
  best: number;
}

/** The view's state: the ranking, or why there is none. */
export type BruteState = { model: BruteModel; message: null } | { model: null; message: string | null };

/** Every choice of m quads ranked best first, ties by mask; `all` holds the
 * values as terrain.enumerateAll() lays them out (choice by choice, every
 * objective in OBJECTIVE_IDS order). */
export function rankChoices(all: ArrayLike<number>, m: number, objective: ObjectiveId, sense: 'min' | 'max'): Ranked[] {
  const k = OBJECTIVE_IDS.indexOf(objective);
  const order = Array.from({ length: 1 << m }, (_, mask) => ({ mask, value: all[mask * OBJECTIVE_IDS.length + k]! }));
  const better = sense === 'min' ? 1 : -1;
  return order.sort((a, b) => better * (a.value - b.value) || a.mask - b.mask);
}

/** The ranking of the terrain's triangulations, or, past MAX_BRUTE_QUADS, why not. */
export function rankTerrain(terrain: Terrain, objective: ObjectiveId, sense: 'min' | 'max'): BruteState {
  const m = terrain.numQuads;
  if (m > MAX_BRUTE_QUADS) {
    return {
      model: null,
      message: `This terrain has ${m} flippable quads: 2^${m} = ${(2 ** m).toLocaleString('en')} triangulations are too many to draw (at most 2^${MAX_BRUTE_QUADS}). Load a small terrain.`,
    };
  }
  const order = rankChoices(terrain.enumerateAll(), m, objective, sense);
  return { model: { terrain, structure: readStructure(terrain), objective, sense, order, best: order[0]!.value }, message: null };
}

/** How the values spread: each distinct value, best first, with how many choices reach it. */
export function valueCounts(order: readonly Ranked[]): [number, number][] {
  const counts = new Map<number, number>();
  for (const x of order) counts.set(x.value, (counts.get(x.value) ?? 0) + 1);
  return [...counts.entries()];
}

export function popcount(x: number): number {
  let c = 0;
  for (; x; x &= x - 1) c++;
  return c;
}

/** Thumbnail size in CSS pixels: fewer cards, larger ones. */
export const thumbSize = (m: number) => (m <= 6 ? 150 : m <= 8 ? 118 : 92);

/** The view's hooks for tests/e2e; `drawn`: thumbnails drawn so far. */
export function bruteHooks(s: BruteState, drawn: number): Record<string, unknown> {
  return {
    message: s.message,
    objective: s.model?.objective ?? null,
    count: s.model?.order.length ?? 0,
    values: s.model?.order.map((x) => x.value) ?? [],
    choices: s.model?.order.map((x) => x.mask) ?? [],
    drawn,
  };
}
