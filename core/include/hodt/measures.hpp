// Every measure of docs/objectives.md on one triangulation. Decisions (edge shape,
// vertex class, extrema) are exact; measured values (areas, angles, radii) are
// doubles computed the same way everywhere, so every solver compares the same numbers.
#pragma once
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "hodt/accurate_det.hpp"
#include "hodt/mesh.hpp"
#include "hodt/progress.hpp"

namespace hodt {

enum EdgeShape : uint8_t { kConvexEdge = 0, kReflexEdge = 1, kFlatEdge = 2, kHullEdge = 3 };
enum VertexClass : uint8_t { kConvex = 0, kConcave = 1, kFlat = 2, kMixed = 3, kBoundary = 4 };
enum Extremum : uint8_t { kNotExtremum = 0, kLocalMinimum = 1, kLocalMaximum = 2 };

// Shape of the interior edge u v whose triangles have apexes w (left of u -> v) and
// x (right): convex if x is strictly below the plane through u, v, w.
EdgeShape edge_shape(const double* u, const double* v, const double* w, const double* x);

// Class of an interior vertex p with neighbours nb (any order). Exact:
// convex iff p is on or above the upper hull of its neighbours over p's (x, y)
// and they are not all coplanar with p; concave symmetrically; flat if coplanar.
// below_known / above_known: neighbours left out are known to put p strictly
// below the upper hull / above the lower hull (star_cone.hpp's marks).
VertexClass vertex_class(const double* p, const double* const* nb, uint32_t count, bool below_known = false,
                         bool above_known = false);
Extremum extremum(const double* p, const double* const* nb, uint32_t count);

// Plane (xy) area of a counterclockwise triangle, positive: within 4 ulps of the
// exact area however thin the triangle, and the same whatever corner comes first
// (accurate_det.hpp). (Inline: the min-max models evaluate it millions of times.)
inline double triangle_area(const double* a, const double* b, const double* c) {
  middle_first(a, b, c);
  return 0.5 * accurate_det(a, b, c);
}
// Bounds on the exact plane area of a counterclockwise triangle by the plain
// float formula, for filters that only need to know that an area is far from
// some bound. The formula's error is at most 4u (|p| + |q|) to first order
// (u = 2^-53; rounded differences and products p, q, and their difference):
// 8u covers the rest. Tight where the products do not cancel, as in every
// cell of a raster at any offset (pairs there tie to within 1e-12, and a fixed
// relative margin would decide none of them); lo <= 0 when cancelling.
struct AreaBounds {
  double lo, hi;
};
inline AreaBounds rough_area_bounds(const double* a, const double* b, const double* c) {
  const double p = (b[0] - a[0]) * (c[1] - a[1]), q = (b[1] - a[1]) * (c[0] - a[0]), det = p - q;
  const double err = 0x1p-50 * (std::abs(p) + std::abs(q));
  return {0.5 * (det - err), 0.5 * (det + err)};
}
// Larger over smaller plane area.
inline double area_ratio(double area1, double area2) { return area1 > area2 ? area1 / area2 : area2 / area1; }
// Angle in [0, pi] between the upward unit normals of two lifted triangles
// (each counterclockwise in xy).
double normal_angle(const double* const t1[3], const double* const t2[3]);
// The same in two steps, for callers that reuse a triangle's normal: the upward
// normal, and the angle between two of them. Each component is a 2x2
// determinant within 4 ulps; the normal is scaled by a power of two (exactly) so
// that its largest component is in [1, 2): angles of normals of any size neither
// overflow nor underflow.
void triangle_normal(const double* const t[3], double n[3]);
double normals_dot(const double n[3], const double m[3]);
double normals_angle(const double n[3], const double m[3]);
// An angle whose normals have a dot product >= 0 is computed as at most pi/2 (plus
// rounding): below this bound.
constexpr double kRightAngleBound = 1.6;
// Radius of the smallest circle containing the four points (plane).
// (Shapes repeated with exact coordinate differences, as in grids, come from a
// cache: the same value, bit for bit.)
double enclosing_circle(const double* a, const double* b, const double* c, const double* d);
namespace detail {
double enclosing_circle_uncached(const double* a, const double* b, const double* c, const double* d);
}
// Radius of the circle through three non-collinear points (plane); its
// denominator is the accurate area, so a sliver's radius is accurate too.
double circumradius(const double* a, const double* b, const double* c);
// Plane length of a segment.
double edge_length(const double* a, const double* b);

// Neighbours of every vertex, counterclockwise, in compressed rows.
struct Stars {
  std::vector<uint32_t> offset;     // size n + 1
  std::vector<uint32_t> neighbor;   // neighbours of v: [offset[v], offset[v+1])
  std::vector<uint32_t> triangle;   // incident triangles, same layout minus boundary gaps
  std::vector<uint32_t> tri_offset;
  std::vector<uint8_t> on_hull;
  uint32_t degree(uint32_t v) const { return offset[v + 1] - offset[v]; }
};
Stars build_stars(const Mesh& mesh, const Progress& progress = {});

// Per-element measures of a triangulation, as arrays (what the API exposes).
// Within a domain (domain.hpp) they are what the objectives count: an edge
// without an inside triangle on each side has no shape (kHullEdge), a vertex
// with a triangle outside no class (kBoundary) and no extremum, and degrees
// count neighbours over inside triangles.
struct Measures {
  std::vector<uint8_t> edge_shape;    // per halfedge (EdgeShape)
  std::vector<uint8_t> vertex_class;  // per vertex (VertexClass)
  std::vector<uint8_t> extremum;      // per vertex (Extremum), interior vertices only
  std::vector<uint32_t> degree;       // per vertex
  std::vector<uint8_t> inside;        // per triangle: 1 if inside the domain (all 1 without one)
};
Measures measure(const Mesh& mesh);

}  // namespace hodt
