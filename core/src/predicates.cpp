#include "hodt/predicates.hpp"

#include <algorithm>
#include <cmath>

#include <CGAL/MP_Float.h>

#include "hodt/kernel.hpp"

namespace hodt {
namespace {
// The semi-static filters are inline in predicates.hpp; what they cannot decide
// comes here.
using detail::kEps;
using detail::kTiny;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;
inline int sign_of(double d) { return (d > 0) - (d < 0); }

// Exact integer arithmetic for the cases the filter cannot decide and that are
// common in practice: grids, whose coordinates are small integers after scaling by
// a power of two (cell sizes like 10, 0.5, 30). Returns false if the coordinates
// are not of that kind; CGAL's exact arithmetic decides those.
bool integer_coords(const double* const* p, int count, int64_t* out) {
  for (double scale = 1; scale <= 256; scale *= 2) {
    bool ok = true;
    for (int i = 0; i < count && ok; ++i)
      for (int k = 0; k < 2 && ok; ++k) {
        const double v = p[i][k] * scale;  // exact: a power of two
        ok = v == std::floor(v) && std::abs(v) < 0x1p24;
        if (ok) out[2 * i + k] = static_cast<int64_t>(v);
      }
    if (ok) return true;
  }
  return false;
}

Point2 p2(const double* p) { return Point2(p[0], p[1]); }
Point3 p3(const double* p) { return Point3(p[0], p[1], p[2]); }
int sign(CGAL::Sign s) { return static_cast<int>(s); }
}  // namespace

int detail::orient2d_exact(const double* a, const double* b, const double* c) {
  const double* pts[3] = {a, b, c};
  int64_t v[6];
  if (integer_coords(pts, 3, v)) {  // |differences| < 2^25: products fit in 64 bits
    const int64_t d = (v[0] - v[4]) * (v[3] - v[5]) - (v[1] - v[5]) * (v[2] - v[4]);
    return (d > 0) - (d < 0);
  }
  return sign(CGAL::orientation(p2(a), p2(b), p2(c)));
}

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
  return sign(CGAL::orientation(p3(a), p3(b), p3(c), p3(d)));
}

int compare_length(const double* a, const double* b, double length) {
  if (length == INFINITY) return -1;  // (coordinates are finite)
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  const double d2 = dx * dx + dy * dy, l2 = length * length;
  // d2 is within 4 eps of |ab|^2 (rounded differences, squares, sum), l2 within
  // one eps of length^2.
  if (std::abs(d2 - l2) > 8 * kEps * (d2 + l2) && d2 + l2 > kTiny && d2 + l2 < INFINITY) return sign_of(d2 - l2);
  using F = CGAL::MP_Float;  // exact sums and products of doubles
  const F x = F(a[0]) - F(b[0]), y = F(a[1]) - F(b[1]), l = F(length);
  return sign(CGAL::compare(x * x + y * y, l * l));
}

int compare_xy(const double* a, const double* b) {  // comparisons of doubles are exact
  return a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : a[1] < b[1] ? -1 : a[1] > b[1] ? 1 : 0;
}

int detail::in_circle_exact(const double* a, const double* b, const double* c, const double* d) {
  const double* pts[4] = {a, b, c, d};
  int64_t v[8];
  if (integer_coords(pts, 4, v)) {  // |differences| < 2^25, lifts < 2^51: 128 bits suffice
    using I = __int128;
    const I ax = v[0] - v[6], ay = v[1] - v[7], bx = v[2] - v[6], by = v[3] - v[7], cx = v[4] - v[6], cy = v[5] - v[7];
    const I al = ax * ax + ay * ay, bl = bx * bx + by * by, cl = cx * cx + cy * cy;
    const I det_exact = al * (bx * cy - cx * by) + bl * (cx * ay - ax * cy) + cl * (ax * by - bx * ay);
    return (det_exact > 0) - (det_exact < 0);
  }
  return sign(CGAL::side_of_oriented_circle(p2(a), p2(b), p2(c), p2(d)));
}

int diametral_sign(const double* p, const double* q, const double* r) {
  const double t1 = (p[0] - r[0]) * (q[0] - r[0]), t2 = (p[1] - r[1]) * (q[1] - r[1]);
  const double dot = t1 + t2, sum = std::abs(t1) + std::abs(t2);
  // Each product is within eps of exact (the differences are rounded too: 3 eps in
  // all per term), the sum adds one more rounding: 4 eps of the sum is safe.
  if (std::abs(dot) > 4.5 * kEps * sum && sum > kTiny) return dot < 0 ? 1 : -1;
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
