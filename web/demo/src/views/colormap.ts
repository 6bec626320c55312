import { Color } from 'three';

/** Hypsometric tints, low to high, muted so that the coloured edges, vertices and
 * quads drawn over them stand out: grey-green lowlands, pale sand, grey-brown
 * slopes, a pale summit. */
const STOPS: ReadonlyArray<readonly [number, string]> = [
  [0.0, '#5f7f70'],
  [0.25, '#8fa88f'],
  [0.5, '#c2c4a6'],
  [0.7, '#d2c3a6'],
  [0.87, '#ad9b8a'],
  [1.0, '#efece6'],
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
