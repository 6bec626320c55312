import { Color } from 'three';

/** Hypsometric tints, low to high: lowland greens, ochre slopes, brown, pale summit. */
const STOPS: ReadonlyArray<readonly [number, string]> = [
  [0.0, '#2f6b4f'],
  [0.2, '#5c9a5a'],
  [0.4, '#a7c27a'],
  [0.58, '#e6d9a0'],
  [0.75, '#c9a06b'],
  [0.9, '#9c7050'],
  [1.0, '#f1ece4'],
];
const COLORS = STOPS.map(([t, hex]) => [t, new Color(hex)] as const);

/** Colour for t in [0, 1] (clamped), interpolated between the stops. */
export function hypsometric(t: number, out = new Color()): Color {
  const u = Math.min(1, Math.max(0, t));
  for (let k = 1; k < COLORS.length; k++) {
    const [t1, c1] = COLORS[k]!;
    if (u <= t1) {
      const [t0, c0] = COLORS[k - 1]!;
      return out.copy(c0).lerp(c1, (u - t0) / (t1 - t0));
    }
  }
  return out.copy(COLORS[COLORS.length - 1]![1]);
}

/** CSS linear-gradient of the colormap, for the legend. */
export function hypsometricGradient(): string {
  return `linear-gradient(90deg, ${STOPS.map(([t, hex]) => `${hex} ${t * 100}%`).join(', ')})`;
}
