import { hypsometricGradient } from '../views/colormap.ts';
import {
  CRITICAL_COLOR,
  EDGE_COLORS,
  EXTREMUM_COLORS,
  FLIPPED_COLOR,
  OUTSIDE_COLOR,
  QUAD_COLOR,
  VERTEX_COLORS,
} from '../views/palette.ts';
import { byId, h } from './dom.ts';

/** The legend strip under the views, built from the shared palette. */
export function renderLegend(): void {
  const swatch = (cls: string, color: string) => h('i', { class: cls, style: `--c: ${color}` });
  const item = (mark: HTMLElement, text: string, title?: string) => h('li', { title }, mark, text);
  const group = (title: string, ...items: HTMLElement[]) => h('ul', {}, h('li', { class: 'group' }, title), ...items);
  byId('legend').replaceChildren(
    group(
      'Edges',
      item(swatch('line', EDGE_COLORS.convex), 'convex (ridge)'),
      item(swatch('line', EDGE_COLORS.reflex), 'reflex (valley)'),
      item(swatch('line', EDGE_COLORS.flat), 'flat'),
      item(swatch('line thick', EDGE_COLORS.hull), 'hull'),
    ),
    group(
      'Vertices',
      item(swatch('dot', VERTEX_COLORS.convex), 'convex'),
      item(swatch('dot', VERTEX_COLORS.concave), 'concave'),
      item(swatch('dot', VERTEX_COLORS.flat), 'flat'),
      item(swatch('dot', VERTEX_COLORS.mixed), 'mixed'),
      item(swatch('dot small', VERTEX_COLORS.boundary), 'boundary'),
      item(swatch('tri down', EXTREMUM_COLORS.minimum), 'local min'),
      item(swatch('tri up', EXTREMUM_COLORS.maximum), 'local max'),
    ),
    group(
      'Quads',
      item(swatch('fill', QUAD_COLOR), 'flippable', 'Either diagonal gives a first order Delaunay triangulation'),
      item(swatch('fill strong', FLIPPED_COLOR), 'diagonal ≠ Delaunay', 'The dashed line (plan view) is the Delaunay diagonal it replaced'),
      item(swatch('fill', CRITICAL_COLOR), 'worst pair', 'The two triangles that attain a min-max objective'),
      item(swatch('fill strong', OUTSIDE_COLOR), 'outside the domain', 'Triangles with an edge longer than the Longest edge setting: not measured by any objective'),
      item(h('i', { class: 'ramp', style: `background: ${hypsometricGradient()}` }), 'elevation (3D)'),
    ),
  );
}
