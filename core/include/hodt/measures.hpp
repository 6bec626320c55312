// Every measure of DEFINITIONS.md on one triangulation. Decisions (edge shape,
// vertex class, extrema) are exact; measured values (areas, angles, radii) are
// doubles computed the same way everywhere, so every solver compares the same numbers.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

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
VertexClass vertex_class(const double* p, const double* const* nb, uint32_t count);
Extremum extremum(const double* p, const double* const* nb, uint32_t count);

// Plane (xy) area of a counterclockwise triangle, positive.
// (Inline: the min-max models evaluate it millions of times.)
inline double triangle_area(const double* a, const double* b, const double* c) {
  // Start at the lexicographically smallest corner, so that the value does not
  // depend on how a mesh happens to list the corners.
  auto less = [](const double* p, const double* q) { return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]); };
  if (less(b, a) && less(b, c)) std::swap(a, b), std::swap(b, c);       // b c a
  else if (less(c, a) && less(c, b)) std::swap(a, c), std::swap(b, c);  // c a b
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}
// Larger over smaller plane area.
inline double area_ratio(double area1, double area2) { return area1 > area2 ? area1 / area2 : area2 / area1; }
// Angle in [0, pi] between the upward unit normals of two lifted triangles
// (each counterclockwise in xy).
double normal_angle(const double* const t1[3], const double* const t2[3]);
// The same in two steps, for callers that reuse a triangle's normal: the upward
// (unnormalised) normal, and the angle between two of them.
void triangle_normal(const double* const t[3], double n[3]);
double normals_dot(const double n[3], const double m[3]);
double normals_angle(const double n[3], const double m[3]);
// An angle whose normals have a dot product >= 0 is computed as at most pi/2 (plus
// rounding): below this bound.
constexpr double kRightAngleBound = 1.6;
// Radius of the smallest circle containing the four points (plane).
double enclosing_circle(const double* a, const double* b, const double* c, const double* d);
// Radius of the circle through three non-collinear points (plane).
double circumradius(const double* a, const double* b, const double* c);
// Plane length of a segment.
double edge_length(const double* a, const double* b);
// A sum that does not depend on the order of its terms (sorted, then added), so
// that equal triangulations listed differently have bit-identical totals.
double order_free_sum(std::vector<double> values, const Progress& progress = {});

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
struct Measures {
  std::vector<uint8_t> edge_shape;    // per halfedge (EdgeShape)
  std::vector<uint8_t> vertex_class;  // per vertex (VertexClass)
  std::vector<uint8_t> extremum;      // per vertex (Extremum), interior vertices only
  std::vector<uint32_t> degree;       // per vertex
};
Measures measure(const Mesh& mesh);

}  // namespace hodt
