/** The colours of the demo, shared by the 3D view, the plan view and the legend.
 * Red means convex (ridges, peaks), blue concave (valleys, pits). */
export const EDGE_COLORS = {
  convex: '#d7263d',
  reflex: '#1f6fd1',
  flat: '#8d9893',
  hull: '#2b3833',
} as const;
/** Indexed by EdgeShape (0 convex, 1 reflex, 2 flat, 3 hull). */
export const EDGE_SHAPE_COLORS = [EDGE_COLORS.convex, EDGE_COLORS.reflex, EDGE_COLORS.flat, EDGE_COLORS.hull] as const;

export const VERTEX_COLORS = {
  convex: '#f0513f',
  concave: '#2f8fe8',
  flat: '#c4cbc7',
  mixed: '#9b45c9',
  boundary: '#3a4641',
} as const;
/** Indexed by VertexClass (0 convex, 1 concave, 2 flat, 3 mixed, 4 boundary). */
export const VERTEX_CLASS_COLORS = [
  VERTEX_COLORS.convex,
  VERTEX_COLORS.concave,
  VERTEX_COLORS.flat,
  VERTEX_COLORS.mixed,
  VERTEX_COLORS.boundary,
] as const;

export const EXTREMUM_COLORS = { minimum: '#0b3d91', maximum: '#8f0d1f' } as const;

/** Flippable quads keeping their Delaunay diagonal, and flipped ones. */
export const QUAD_COLOR = '#19b3a6';
export const FLIPPED_COLOR = '#ffb000';
/** The two triangles that attain a min-max objective's value. */
export const CRITICAL_COLOR = '#e5198a';
export const SELECTION_COLOR = '#111111';
/** Triangles outside the domain (an edge longer than maxEdge): not measured. */
export const OUTSIDE_COLOR = '#59605d';
/** Useful order-k Delaunay edges (edges of some order-k triangulation). */
export const USEFUL_COLOR = '#7b3fe4';
