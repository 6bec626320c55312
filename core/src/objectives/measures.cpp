#include "hodt/measures.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "hodt/domain.hpp"
#include "hodt/predicates.hpp"
#include "containers/out_of_line.hpp"
#include "containers/recent_values.hpp"
#include "geometry/kernel.hpp"
#include "geometry/portable_math.hpp"
#include "objectives/objective_terms.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

EdgeShape edge_shape(const double* u, const double* v, const double* w, const double* x) {
  const int o = orient3d(u, v, w, x);
  return o < 0 ? kConvexEdge : o > 0 ? kReflexEdge : kFlatEdge;
}

Extremum extremum(const double* p, const double* const* nb, uint32_t d) {
  bool all_higher = true, all_lower = true;
  for (uint32_t i = 0; i < d; ++i) {
    all_higher = all_higher && nb[i][2] > p[2];
    all_lower = all_lower && nb[i][2] < p[2];
  }
  return all_higher ? kLocalMinimum : all_lower ? kLocalMaximum : kNotExtremum;
}

namespace {
bool xy_less(const double* p, const double* q) { return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]); }
// 1 / 2^e for the binade [2^e, 2^(e+1)) of a positive normal double x: the
// power of two that scales x into [1, 2), read off its exponent bits (cheaper
// than ilogb and ldexp; exact and the same on every platform).
// (memcpy, not std::bit_cast: Emscripten 3.1.6's libc++ lacks it.)
double inverse_binade(double x) {
  uint64_t bits;  // (memcpy: emscripten 3.1.6's libc++ has no std::bit_cast)
  std::memcpy(&bits, &x, sizeof bits);
  bits = (2046 - (bits >> 52)) << 52;  // biased exponent e + 1023 (1..2046) -> 1023 - e
  double inverse;
  std::memcpy(&inverse, &bits, sizeof inverse);
  return inverse;
}
}  // namespace

void triangle_normal(const double* const t[3], double n[3]) {
  // (b - a) x (c - a): each component the determinant of one coordinate plane.
  const double *a = t[0], *b = t[1], *c = t[2];
  middle_first(a, b, c);  // the same normal for every rotation of the corners
  n[0] = accurate_det(a, b, c, 1, 2);
  n[1] = accurate_det(a, b, c, 2, 0);
  n[2] = accurate_det(a, b, c, 0, 1);
  // Largest component into [1, 2). In the coordinate range every nonzero
  // component is in [2^-404, 2^303], so the scaled ones stay normal numbers:
  // the scaling is exact, and angles (ratios) are those of the unscaled normal.
  const double top = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
  if (top == 0) return;
  const double scale = inverse_binade(top);
  for (int k = 0; k < 3; ++k) n[k] *= scale;
}

double normals_dot(const double n[3], const double m[3]) { return n[0] * m[0] + n[1] * m[1] + n[2] * m[2]; }

double normals_angle(const double n[3], const double m[3]) {
  const double cx = n[1] * m[2] - n[2] * m[1], cy = n[2] * m[0] - n[0] * m[2],
               cz = n[0] * m[1] - n[1] * m[0];
  return portable_angle(std::sqrt(cx * cx + cy * cy + cz * cz), normals_dot(n, m));
}

double normal_angle(const double* const t1[3], const double* const t2[3]) {
  double n[3], m[3];
  triangle_normal(t1, n);
  triangle_normal(t2, m);
  return normals_angle(n, m);
}

double edge_length(const double* a, const double* b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];  // symmetric: (-d)^2 = d^2 exactly
  return std::sqrt(dx * dx + dy * dy);              // sqrt is correctly rounded everywhere
}

namespace {
// The radius of four points sorted by xy_less, from scratch.
double sorted_enclosing_circle(const double* const p[4]) {
  // The smallest enclosing circle has two or three of the points on its boundary:
  // the smallest candidate that contains all four (decided exactly) is the answer.
  double best = INFINITY;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      bool ok = true;
      for (int k = 0; k < 4 && ok; ++k)
        if (k != i && k != j) ok = diametral_sign(p[i], p[j], p[k]) >= 0;
      if (ok) best = std::min(best, 0.5 * edge_length(p[i], p[j]));
    }
  for (int skip = 0; skip < 4; ++skip) {
    const double* t[3];
    int n = 0;
    for (int k = 0; k < 4; ++k)
      if (k != skip) t[n++] = p[k];
    const int o = orient2d(t[0], t[1], t[2]);
    if (o == 0 || in_circle_sign(t[0], t[1], t[2], p[skip]) * o < 0) continue;
    best = std::min(best, circumradius(t[0], t[1], t[2]));
  }
  return best;
}

// Grids (DEM rasters, at any offset) repeat a few shapes over and over, and there
// every pair of cocircular cells needs the exact predicates. Every step above
// (exact signs, xy order, and lengths and determinants from rounded differences
// with their errors) is a function of the points' exact pairwise differences.
// When the differences to the first point are exact doubles they determine all
// the others: four points with the same differences to the first get the same
// radius, bit for bit, and recent shapes are remembered by those differences.
bool shape_key(const double* const p[4], double key[6]) {
  for (int j = 1; j < 4; ++j)
    for (int c = 0; c < 2; ++c) {
      const Difference d = difference(p[j][c], p[0][c]);
      if (d.e != 0) return false;
      key[2 * (j - 1) + c] = d.d;
    }
  return true;
}
}  // namespace

double enclosing_circle(const double* a, const double* b, const double* c, const double* d) {
  // Sorted, so that the radius does not depend on the order of the arguments.
  const double* p[4] = {a, b, c, d};
  std::sort(p, p + 4, xy_less);
  std::array<double, 6> key;
  if (!shape_key(p, key.data())) return sorted_enclosing_circle(p);
  static thread_local RecentValues<6, double, kBudgets.recent_circles> recent;
  return recent.get(key, [&] { return sorted_enclosing_circle(p); });
}

double detail::enclosing_circle_uncached(const double* a, const double* b, const double* c, const double* d) {
  const double* p[4] = {a, b, c, d};
  std::sort(p, p + 4, xy_less);
  return sorted_enclosing_circle(p);
}

double circumradius(const double* a, const double* b, const double* c) {
  // |ab| |bc| |ca| / (4 area), each factor computed the same way on every platform.
  middle_first(a, b, c);
  const double area2 = std::abs(accurate_det(a, b, c));
  return edge_length(a, b) * edge_length(b, c) * edge_length(c, a) / (2 * area2);
}

Stars build_stars(const Mesh& m, const Progress& progress) {
  const uint32_t n = m.num_vertices();
  const std::vector<int32_t> start = vertex_halfedges(m);
  Stars s;
  s.offset.assign(n + 1, 0);
  s.tri_offset.assign(n + 1, 0);
  s.on_hull.assign(n, 0);
  s.neighbor.reserve(m.triangles.size() + m.hull.size());
  s.triangle.reserve(m.triangles.size());
  WorkCounter work;
  for_each_index(n, [&](uint32_t v) {  // (in chunks: see out_of_line.hpp)
    if (work.tick(64)) report(progress, v, n);
    s.offset[v] = static_cast<uint32_t>(s.neighbor.size());
    s.tri_offset[v] = static_cast<uint32_t>(s.triangle.size());
    if (start[v] < 0) return;
    s.on_hull[v] = m.halfedges[static_cast<uint32_t>(start[v])] < 0;
    walk_star(m, static_cast<uint32_t>(start[v]), [&](uint32_t w, uint32_t t) {
      s.neighbor.push_back(w);
      if (t != UINT32_MAX) s.triangle.push_back(t);
    });
  });
  s.offset[n] = static_cast<uint32_t>(s.neighbor.size());
  s.tri_offset[n] = static_cast<uint32_t>(s.triangle.size());
  return s;
}

Measures measure(const Mesh& m) {
  Measures r;
  const uint32_t n = m.num_vertices();
  r.inside = inside_triangles(m);
  r.edge_shape.assign(m.triangles.size(), kHullEdge);
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (f < 0 || !r.inside[e / 3] || !r.inside[static_cast<uint32_t>(f) / 3]) continue;
    r.edge_shape[e] = edge_shape(m.point(m.origin(e)), m.point(m.target(e)), m.point(m.apex(e)),
                                 m.point(m.apex(static_cast<uint32_t>(f))));
  }
  const Stars s = build_stars(m);
  r.vertex_class.assign(n, kBoundary);
  r.extremum.assign(n, kNotExtremum);
  r.degree.assign(n, 0);
  std::vector<const double*> nb;
  std::vector<uint32_t> inside_nb;
  std::vector<Tri> inside_tris;
  for (uint32_t v = 0; v < n; ++v) {
    const uint32_t d = s.degree(v);
    r.degree[v] = d;
    if (has_domain(m)) {
      inside_tris.clear();
      for (uint32_t i = s.tri_offset[v]; i < s.tri_offset[v + 1]; ++i)
        if (r.inside[s.triangle[i]]) inside_tris.push_back(base_triangle(m, s.triangle[i]));
      star_neighbors(v, inside_tris, inside_nb);
      r.degree[v] = static_cast<uint32_t>(inside_nb.size());
      if (inside_tris.size() != s.tri_offset[v + 1] - s.tri_offset[v]) continue;  // (not counted: no class)
    }
    if (s.on_hull[v]) continue;
    nb.resize(d);
    for (uint32_t k = 0; k < d; ++k) nb[k] = m.point(s.neighbor[s.offset[v] + k]);
    r.vertex_class[v] = vertex_class(m.point(v), nb.data(), d);
    r.extremum[v] = extremum(m.point(v), nb.data(), d);
  }
  return r;
}

}  // namespace hodt
