#include "objectives/pair_measures.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "hodt/domain.hpp"
#include "hodt/measures.hpp"
#include "containers/recent_values.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

namespace {

// The accurate areas and normals of the triangles measured last: a star's
// triangles recur in its pairs (on a grid every pair needs them: its areas tie).
double area(const Mesh& m, const Tri& t) {
  static thread_local RecentValues<6, double> recent;
  const double *a = m.point(t[0]), *b = m.point(t[1]), *c = m.point(t[2]);
  return recent.get({a[0], a[1], b[0], b[1], c[0], c[1]}, [&] { return triangle_area(a, b, c); });
}

std::array<double, 3> normal(const Mesh& m, const Tri& t) {
  static thread_local RecentValues<9, std::array<double, 3>> recent;
  const double* c[3] = {m.point(t[0]), m.point(t[1]), m.point(t[2])};
  return recent.get({c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0], c[2][1], c[2][2]}, [&] {
    std::array<double, 3> n;
    triangle_normal(c, n.data());
    return n;
  });
}

// cos(cut), recomputed only when the cut changes (it is a slowly rising max).
double cos_of(double cut) {
  static thread_local double last = NAN, value = NAN;
  if (cut != last) last = cut, value = std::cos(cut);
  return value;
}

// sin(cut - margin), recomputed only when they change.
double sin_below(double cut, double margin) {
  static thread_local double last = NAN, last_margin = NAN, value = NAN;
  if (cut != last || margin != last_margin) last = cut, last_margin = margin, value = std::sin(cut - margin);
  return value;
}

double cross_length(const double n[3], const double k[3]) {
  const double cx = n[1] * k[2] - n[2] * k[1], cy = n[2] * k[0] - n[0] * k[2], cz = n[0] * k[1] - n[1] * k[0];
  return std::sqrt(cx * cx + cy * cy + cz * cz);
}

// Whether two normals (cross the length of their cross product, x their dot
// product, norms the product of their lengths) are at an angle below
// cut - margin + 2^-48. A small angle's cosine is near 1, where a margin in
// cosine is a large one in angle (2^-20 is 1% of an angle of 0.01); its sine
// is well conditioned: the computed cross is within 5u norms of the exact one,
// the sine's own rounding is covered by 2^-40, and with x > 0 and cut <= 1 the
// angle is below pi/2 and its cosine above 1/2: the angle is within 2^-49 of
// the sine's bound. (Smooth terrain: neighbouring normals differ by small
// angles, and so does the cut.) With norms in [1e-140, 1e140] and the angle
// above the margin, the cross product's squares neither underflow nor overflow.
bool small_angle_below(double cross, double x, double norms, double cut, double margin) {
  return x > 0 && cut <= 1 && cut > margin && norms > 1e-140 && norms < 1e140 &&
         cross <= norms * sin_below(cut, margin) * (1 - 0x1p-40);
}

// The angle of two normals, or 0 when it is at most cut. The angle is
// portable_angle(y, x) of y = |n x k| and x = n . k, within 1e-15 of atan2(y, x),
// and atan2(y, x) < cut - 1e-15 when x / |(x, y)| exceeds cos(cut) by the margin
// (which also covers the rounding of cos, the norm and the product). Saves the
// arctangent; with x >= 0 and a cut past pi/2 even the cross product.
double angle_above(const std::array<double, 3>& n, const std::array<double, 3>& k, double cut) {
  const double x = normals_dot(n.data(), k.data());
  if (cut >= kRightAngleBound && x >= 0) return 0;
  if (cut > 0) {
    const double cross = cross_length(n.data(), k.data()), r = std::sqrt(cross * cross + x * x);
    if (r > 1e-140 && r < 1e140 &&  // (no underflow or overflow)
        (x >= r * (cos_of(cut) + 1e-9) || small_angle_below(cross, x, r, cut, 0x1p-40)))
      return 0;
  }
  return normals_angle(n.data(), k.data());
}

AreaBounds rough_area(const Mesh& m, const Tri& t) { return rough_area_bounds(m.point(t[0]), m.point(t[1]), m.point(t[2])); }
}  // namespace

double pair_area_ratio(const Mesh& m, const Tri& s, const Tri& t) { return area_ratio(area(m, s), area(m, t)); }

double pair_area_ratio(const Mesh& m, const Tri& s, const Tri& t, double cut) {
  // The exact ratio is at most the bounds' ratio, and the accurate one (areas
  // within 4 ulps) within 2^-47 of the exact one: with the margin 2^-46 (which
  // also covers this division's rounding) it is at most the cut. Most pairs end
  // here, on a raster too, where the cut is within 1e-11 of 1.
  const AreaBounds a = rough_area(m, s), b = rough_area(m, t);
  if (a.lo > 0 && b.lo > 0 && std::max(a.hi / b.lo, b.hi / a.lo) * (1 + 0x1p-46) <= cut) return cut;
  return pair_area_ratio(m, s, t);
}

bool star_area_ratio_below(const Mesh& m, const Tri* t, size_t n, double cut) {
  // Every pair's ratio is at most the largest bound over the least (the margin
  // as for one pair).
  double lo = INFINITY, hi = 0;
  for (size_t i = 0; i < n; ++i) {
    const AreaBounds a = rough_area(m, t[i]);
    lo = std::min(lo, a.lo), hi = std::max(hi, a.hi);
  }
  return lo > 0 && hi / lo * (1 + 0x1p-46) <= cut;
}

double pair_normal_angle(const Mesh& m, const Tri& s, const Tri& t) {
  const double* a[3] = {m.point(s[0]), m.point(s[1]), m.point(s[2])};
  const double* b[3] = {m.point(t[0]), m.point(t[1]), m.point(t[2])};
  return normal_angle(a, b);
}

namespace {
// A triangle's normal (b - a) x (c - a) by the plain float formula, if it can be
// trusted: each component is within 3u S + u |n_k| <= 4u S of the exact one
// (u = 2^-53, S = |p| + |q| of its two products), so with every S <= 2^21 max
// |n_k| the normal is within 2^-30 max |n_k| per component, 2^-29 |n| in length:
// its direction within 2^-29 radians.
bool rough_normal(const Mesh& m, const Tri& t, double n[3]) {
  const double *a = m.point(t[0]), *b = m.point(t[1]), *c = m.point(t[2]);
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  double top = 0, sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double p = u[(k + 1) % 3] * v[(k + 2) % 3], q = u[(k + 2) % 3] * v[(k + 1) % 3];
    n[k] = p - q;
    top = std::max(top, std::abs(n[k]));
    sum = std::max(sum, std::abs(p) + std::abs(q));
  }
  return sum <= 0x1p21 * top;
}
}  // namespace

double pair_normal_angle(const Mesh& m, const Tri& s, const Tri& t, double cut) {
  // Rough normals within 2^-29 radians each: when the cosine of their angle
  // exceeds cos(cut) by 2^-20 (far more than its rounding), their angle is below
  // cut - 2^-20 and the exact one below cut. Most pairs end here. (In the
  // coordinate range |n|^2 < 2^608 and a product of two would overflow: the
  // norms are taken one by one.)
  // Small angles by their sine: within 2^-28 radians for the two rough
  // normals, the margin 2^-26 covers it.
  double n[3], k[3];
  if (cut > 0 && rough_normal(m, s, n) && rough_normal(m, t, k)) {
    const double x = normals_dot(n, k), norms = std::sqrt(normals_dot(n, n)) * std::sqrt(normals_dot(k, k));
    if (x >= norms * (cos_of(cut) + 0x1p-20) || small_angle_below(cross_length(n, k), x, norms, cut, 0x1p-26)) return 0;
  }
  return angle_above(normal(m, s), normal(m, t), cut);
}

bool star_normal_angle_below(const Mesh& m, const Tri* t, size_t n, double cut) {
  // Each rough normal within cut / 2 - 2^-26 (+ 2^-48) of some axis: any two
  // within cut - 2^-25 of each other, the exact ones within 2^-28 more. The
  // axis: the sum of the unit normals (any vector will do, a central one
  // passes most stars).
  if (n == 0 || n > 64 || cut / 2 > 1) return false;  // (past 1: the sine test declines every normal)
  double normals[64][3], norm[64], axis[3] = {0, 0, 0};
  for (size_t i = 0; i < n; ++i) {
    if (!rough_normal(m, t[i], normals[i])) return false;
    norm[i] = std::sqrt(normals_dot(normals[i], normals[i]));
    for (int c = 0; c < 3; ++c) axis[c] += normals[i][c] / norm[i];
  }
  const double axis_norm = std::sqrt(normals_dot(axis, axis));
  for (size_t i = 0; i < n; ++i)
    if (!small_angle_below(cross_length(axis, normals[i]), normals_dot(axis, normals[i]), axis_norm * norm[i], cut / 2,
                           0x1p-26))
      return false;
  return true;
}

double pair_enclosing_circle(const Mesh& m, const Tri& s, const Tri& t, double cut) {
  // Jung's theorem: four points at most D apart lie in a circle of radius D / sqrt(3).
  // D^2 in floats is within 4u of the exact one: with the margin 2^-20 below the
  // cut, the exact radius and the accurate one are below it.
  if (cut > 0) {
    const double* p[4] = {m.point(s[0]), m.point(s[1]), m.point(s[2]), nullptr};
    for (uint32_t v : t)
      if (v != s[0] && v != s[1] && v != s[2]) p[3] = m.point(v);
    double d2 = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const double dx = p[j][0] - p[i][0], dy = p[j][1] - p[i][1];
        d2 = std::max(d2, dx * dx + dy * dy);
      }
    if (d2 * (1 + 0x1p-20) <= 3 * cut * cut) return cut;
  }
  return pair_enclosing_circle(m, s, t);
}

double pair_enclosing_circle(const Mesh& m, const Tri& s, const Tri& t) {
  // The vertex of t that is not in s.
  uint32_t d = t[0];
  for (uint32_t v : t)
    if (v != s[0] && v != s[1] && v != s[2]) d = v;
  return enclosing_circle(m.point(s[0]), m.point(s[1]), m.point(s[2]), m.point(d));
}

bool is_pair_objective(Objective o) { return objective_terms_inside(o).measure != PairMeasure::None; }

namespace {

// The first pair (edge- or vertex-adjacent, in mesh order) of largest value. A
// feature of each triangle (its area, normal...) is computed once per edge or
// star; value(fa, fb, cut) may answer anything <= cut for a pair that cannot win.
// below: a value under the largest (pairs at most it answer as cut).
template <class Feature, class Value>
std::optional<CriticalPair> first_largest_pair(const Mesh& m, bool edge, Feature feature, Value value, double below,
                                               const Progress& progress) {
  std::optional<CriticalPair> best;
  WorkCounter work;
  const std::vector<uint8_t> inside = inside_triangles(m);  // (pairs of inside triangles only)
  auto consider = [&](uint32_t s, uint32_t t, const auto& fs, const auto& ft) {
    if (!inside[s] || !inside[t]) return;
    const double v = value(fs, ft, best ? std::max(best->value, below) : below);
    if (!best || v > best->value) best = CriticalPair{base_triangle(m, s), base_triangle(m, t), v};
  };
  if (edge) {
    for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
      const int32_t f = m.halfedges[e];
      if (f > static_cast<int32_t>(e)) consider(e / 3, f / 3, feature(e / 3), feature(static_cast<uint32_t>(f) / 3));
      if (work.tick(32)) report(progress, e, m.halfedges.size());
    }
    return best;
  }
  const Stars st = build_stars(m, progress);
  std::vector<decltype(feature(0u))> star;
  for (uint32_t v = 0; v < m.num_vertices(); ++v) {
    const uint32_t b = st.tri_offset[v], e = st.tri_offset[v + 1];
    star.clear();
    for (uint32_t i = b; i < e; ++i) star.push_back(feature(st.triangle[i]));
    for (uint32_t i = b; i < e; ++i)
      for (uint32_t j = i + 1; j < e; ++j) consider(st.triangle[i], st.triangle[j], star[i - b], star[j - b]);
    if (work.tick(16.0 * (e - b) * (e - b))) report(progress, v, m.num_vertices());
  }
  return best;
}

}  // namespace

namespace {
std::optional<CriticalPair> largest_pair(Objective o, const Mesh& m, double below, const Progress& progress) {
  // Edges: the best value so far is the cut, and float estimates show most pairs
  // below it (only the few that raise it get accurate measures). Stars: each
  // triangle's accurate area or normal once per star, as its pairs there share it.
  auto tri = [&](uint32_t t) { return base_triangle(m, t); };
  auto tri_area = [&](uint32_t t) { return area(m, tri(t)); };
  auto tri_normal = [&](uint32_t t) { return normal(m, tri(t)); };
  auto ratio = [](double a, double b, double) { return area_ratio(a, b); };
  auto ratio_above = [&](const Tri& a, const Tri& b, double cut) { return pair_area_ratio(m, a, b, cut); };
  auto angle = [&](const Tri& a, const Tri& b, double cut) { return pair_normal_angle(m, a, b, cut); };
  auto circle = [&](const Tri& a, const Tri& b, double cut) { return pair_enclosing_circle(m, a, b, cut); };
  const ObjectiveTerms& d = objective_terms_inside(o);
  const bool edge = d.site == TermSite::EdgePair;
  switch (d.measure) {
    case PairMeasure::AreaRatio:
      return edge ? first_largest_pair(m, true, tri, ratio_above, below, progress)
                  : first_largest_pair(m, false, tri_area, ratio, below, progress);
    case PairMeasure::NormalAngle:
      return edge ? first_largest_pair(m, true, tri, angle, below, progress)
                  : first_largest_pair(m, false, tri_normal, angle_above, below, progress);
    case PairMeasure::EnclosingCircle:
      if (!edge) throw std::logic_error("an enclosing circle of two triangles sharing only a vertex");
      return first_largest_pair(m, true, tri, circle, below, progress);
    case PairMeasure::None: break;
  }
  return std::nullopt;
}

}  // namespace

std::optional<CriticalPair> critical_pair(Objective o, const Mesh& m, const Progress& progress, double expected) {
  // With the value expected, every pair under it answers as a cut from the
  // start; should the largest not exceed the cut after all, search again.
  if (expected > -INFINITY) {
    const double below = std::nextafter(expected, -INFINITY);
    std::optional<CriticalPair> c = largest_pair(o, m, below, progress);
    if (c && c->value > below) return c;
  }
  return largest_pair(o, m, -INFINITY, progress);
}

}  // namespace hodt
