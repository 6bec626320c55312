#include "hodt/predicates.hpp"

#include <algorithm>
#include <cmath>

#include <CGAL/MP_Float.h>

#include "hodt/accurate_det.hpp"
#include "geometry/kernel.hpp"
#include "geometry/wide_int.hpp"

namespace hodt {
namespace {
// The semi-static filters are inline in predicates.hpp; what they cannot decide
// comes here.
using detail::kEps;
using detail::kTiny;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;
inline int sign_of(double d) { return (d > 0) - (d < 0); }

// Exact integer arithmetic for the cases the filter cannot decide and that are
// common in practice: grids and quantised point clouds, in any coordinates. The
// predicates read only differences to the last point; between nearby points of
// one binade those are exact doubles (Sterbenz), and then all of them are
// integers times one power of two: a georeferenced grid (x = 731012.3456789 +
// 74.98765 i) as much as an integer one. Scaled to integers below 2^62 they give
// the determinants exactly in 128 or 256 bits (wide_int.hpp), with no allocation.
// Returns false if a difference is not exact or the integers would be too wide;
// CGAL's exact arithmetic decides those.
constexpr int kMaxPoints = 4;
struct Scaled {
  int64_t v[3 * kMaxPoints];  // per point but the last: its differences to the last, scaled
  int64_t largest = 0;        // the largest |v| of the coordinates asked
};
bool scaled_differences(const double* const* p, int count, int first, int dims, Scaled& out) {
  double d[3 * kMaxPoints];
  int low = INT32_MAX;  // the smallest ulp exponent among the nonzero differences
  const double* last = p[count - 1];
  for (int i = 0; i + 1 < count; ++i)
    for (int k = first; k < first + dims; ++k) {
      const Difference diff = difference(p[i][k], last[k]);
      if (diff.e != 0) return false;
      d[dims * i + k - first] = diff.d;
      if (diff.d != 0) low = std::min(low, std::ilogb(diff.d) - 52);
    }
  out.largest = 0;
  // 2^-low is a normal double: nonzero differences lie within 2^-202 .. 2^151 in
  // the coordinate range (points.hpp), so low is within -254 .. 99, and scaling
  // by a power of two is exact.
  const double scale = low == INT32_MAX ? 1 : std::ldexp(1.0, -low);
  for (int j = 0; j < dims * (count - 1); ++j) {
    if (d[j] == 0) {
      out.v[j] = 0;
      continue;
    }
    const double v = d[j] * scale;  // an integer, exactly (a power of two)
    if (!(std::abs(v) < 0x1p62)) return false;
    out.v[j] = static_cast<int64_t>(v);
    out.largest = std::max(out.largest, std::abs(out.v[j]));
  }
  return true;
}

Point2 p2(const double* p) { return Point2(p[0], p[1]); }
Point3 p3(const double* p) { return Point3(p[0], p[1], p[2]); }
int sign(CGAL::Sign s) { return static_cast<int>(s); }
}  // namespace

int detail::orient2d_exact(const double* a, const double* b, const double* c) {
  const double* pts[3] = {a, b, c};
  Scaled s;
  if (scaled_differences(pts, 3, 0, 2, s)) {  // products below 2^124
    const int64_t* v = s.v;
    const Int128 d = static_cast<Int128>(v[0]) * v[3] - static_cast<Int128>(v[1]) * v[2];
    return (d > 0) - (d < 0);
  }
  return sign(CGAL::orientation(p2(a), p2(b), p2(c)));
}

namespace {
// The 3x3 determinant of rows (x, y, z) per point, exactly; `lift` true takes z =
// x^2 + y^2 (the in-circle test). Below 2^30 everything fits in 128 bits.
template <typename Z>
int det3_sign(const int64_t* x, const int64_t* y, Z z, bool narrow) {
  const auto minor = [&](int i, int j) { return static_cast<Int128>(x[i]) * y[j] - static_cast<Int128>(x[j]) * y[i]; };
  const Int128 bc = minor(1, 2), ca = minor(2, 0), ab = minor(0, 1);
  if (narrow) {
    const Int128 d = z(0) * bc + z(1) * ca + z(2) * ab;
    return (d > 0) - (d < 0);
  }
  return (Int256::product(z(0), bc) + Int256::product(z(1), ca) + Int256::product(z(2), ab)).sign();
}
}  // namespace

int orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  // Shewchuk's orient3d is positive when d is below the plane of counterclockwise
  // a, b, c; ours is positive above, hence the minus.
  const double det = adz * bc + bdz * ca + cdz * ab;
  const double perm = (std::abs(bdx * cdy) + std::abs(cdx * bdy)) * std::abs(adz) +
                      (std::abs(cdx * ady) + std::abs(adx * cdy)) * std::abs(bdz) +
                      (std::abs(adx * bdy) + std::abs(bdx * ady)) * std::abs(cdz);
  if (std::abs(det) > kOrient3dBound * perm && perm > kTiny) return -sign_of(det);
  // Exactly: xy and z scaled apart (the sign does not change).
  const double* pts[4] = {a, b, c, d};
  Scaled xy, z;
  if (scaled_differences(pts, 4, 0, 2, xy) && scaled_differences(pts, 4, 2, 1, z)) {
    const int64_t x[3] = {xy.v[0], xy.v[2], xy.v[4]}, y[3] = {xy.v[1], xy.v[3], xy.v[5]};
    const bool narrow = xy.largest < (int64_t{1} << 30) && z.largest < (int64_t{1} << 30);
    return -det3_sign(x, y, [&](int i) { return static_cast<Int128>(z.v[i]); }, narrow);
  }
  return sign(CGAL::orientation(p3(a), p3(b), p3(c), p3(d)));
}

int detail::compare_length_exact(const double* a, const double* b, double length) {
  using F = CGAL::MP_Float;  // exact sums and products of doubles
  const F x = F(a[0]) - F(b[0]), y = F(a[1]) - F(b[1]), l = F(length);
  return sign(CGAL::compare(x * x + y * y, l * l));
}

int detail::compare_descents_exact(const double* v, const double* a, const double* b) {
  // Grids with heights in fixed steps (integer metres, centimetres) tie often:
  // scaled to integers, xy below 2^62 gives squared lengths below 2^125, z below
  // 2^62 squared drops below 2^124, and D in 256 bits.
  const double* pts[3] = {a, b, v};
  Scaled xy, z;
  if (scaled_differences(pts, 3, 0, 2, xy) && scaled_differences(pts, 3, 2, 1, z)) {
    const auto sq = [](int64_t x) { return static_cast<Int128>(x) * x; };
    const Int128 la = sq(xy.v[0]) + sq(xy.v[1]), lb = sq(xy.v[2]) + sq(xy.v[3]);
    return (Int256::product(sq(z.v[0]), lb) + Int256::product(sq(z.v[1]), la).negated()).sign();
  }
  using F = CGAL::MP_Float;  // exact sums and products of doubles
  const F za = F(v[2]) - F(a[2]), zb = F(v[2]) - F(b[2]);
  const F xa = F(v[0]) - F(a[0]), ya = F(v[1]) - F(a[1]), xb = F(v[0]) - F(b[0]), yb = F(v[1]) - F(b[1]);
  return sign(CGAL::compare(za * za * (xb * xb + yb * yb), zb * zb * (xa * xa + ya * ya)));
}

int compare_xy(const double* a, const double* b) {  // comparisons of doubles are exact
  return a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : a[1] < b[1] ? -1 : a[1] > b[1] ? 1 : 0;
}

int detail::in_circle_exact(const double* a, const double* b, const double* c, const double* d) {
  const double* pts[4] = {a, b, c, d};
  Scaled s;
  if (scaled_differences(pts, 4, 0, 2, s)) {  // lifts below 2^125, the determinant below 2^252
    const int64_t x[3] = {s.v[0], s.v[2], s.v[4]}, y[3] = {s.v[1], s.v[3], s.v[5]};
    const auto lift = [&](int i) { return static_cast<Int128>(x[i]) * x[i] + static_cast<Int128>(y[i]) * y[i]; };
    return det3_sign(x, y, lift, s.largest < (int64_t{1} << 30));
  }
  return sign(CGAL::side_of_oriented_circle(p2(a), p2(b), p2(c), p2(d)));
}

int diametral_sign(const double* p, const double* q, const double* r) {
  const double t1 = (p[0] - r[0]) * (q[0] - r[0]), t2 = (p[1] - r[1]) * (q[1] - r[1]);
  const double dot = t1 + t2, sum = std::abs(t1) + std::abs(t2);
  // Each product is within eps of exact (the differences are rounded too: 3 eps in
  // all per term), the sum adds one more rounding: 4 eps of the sum is safe.
  if (std::abs(dot) > 4.5 * kEps * sum && sum > kTiny) return dot < 0 ? 1 : -1;
  const double* pts[3] = {p, q, r};
  Scaled sd;
  if (scaled_differences(pts, 3, 0, 2, sd)) {  // (right angles of grid cells come here)
    const Int128 exact = static_cast<Int128>(sd.v[0]) * sd.v[2] + static_cast<Int128>(sd.v[1]) * sd.v[3];
    return exact < 0 ? 1 : exact == 0 ? 0 : -1;
  }
  const CGAL::Bounded_side s = CGAL::side_of_bounded_circle(p2(p), p2(q), p2(r));
  return s == CGAL::ON_BOUNDED_SIDE ? 1 : s == CGAL::ON_BOUNDARY ? 0 : -1;
}

// Mirrors Triangulation_2::side_of_oriented_circle(p0, p1, p2, p, perturb = true)
// so that this predicate and CGAL's Delaunay triangulation decide degenerate
// (cocircular) cases the same way.
bool detail::in_circle_perturbed(const double* a, const double* b, const double* c, const double* d) {
  const Point2 p0 = p2(a), p1 = p2(b), q2 = p2(c), p = p2(d);
  const Point2* pts[4] = {&p0, &p1, &q2, &p};
  std::sort(pts, pts + 4, [](const Point2* u, const Point2* v) {
    return CGAL::compare_xy(*u, *v) == CGAL::SMALLER;
  });
  for (int i = 3; i > 0; --i) {
    if (pts[i] == &p) return false;
    CGAL::Orientation o;
    if (pts[i] == &q2 && (o = CGAL::orientation(p0, p1, p)) != CGAL::COLLINEAR)
      return o == CGAL::POSITIVE;
    if (pts[i] == &p1 && (o = CGAL::orientation(p0, p, q2)) != CGAL::COLLINEAR)
      return o == CGAL::POSITIVE;
    if (pts[i] == &p0 && (o = CGAL::orientation(p, p1, q2)) != CGAL::COLLINEAR)
      return o == CGAL::POSITIVE;
  }
  return false;
}

}  // namespace hodt
