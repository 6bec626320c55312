// Exact geometric decisions. Every yes/no question of the project goes through
// these functions; measured values (areas, angles) live in measures.hpp.
#pragma once
#include <cmath>
#include <cstdint>

namespace hodt {

namespace detail {
// Semi-static filters (Shewchuk, "Adaptive precision floating-point arithmetic",
// error bounds A), inline because they decide almost every call: in
// round-to-nearest the double evaluation's sign is right when |det| exceeds the
// bound. The bounds assume no underflow, so tiny permanents go to the exact path
// (64/128-bit integers for grid-like coordinates, else CGAL) in predicates.cpp.
constexpr double kEps = 0x1p-53;
constexpr double kOrient2dBound = (3.0 + 16.0 * kEps) * kEps;
constexpr double kInCircleBound = (10.0 + 96.0 * kEps) * kEps;
constexpr double kTiny = 0x1p-900;
int orient2d_exact(const double* a, const double* b, const double* c);
int in_circle_exact(const double* a, const double* b, const double* c, const double* d);
int compare_length_exact(const double* a, const double* b, double length);
int compare_descents_exact(const double* v, const double* a, const double* b);
bool in_circle_perturbed(const double* a, const double* b, const double* c, const double* d);
}  // namespace detail

// Sign of the xy orientation of (a, b, c): +1 counterclockwise, -1 clockwise, 0 collinear.
inline int orient2d(const double* a, const double* b, const double* c) {
  const double l = (a[0] - c[0]) * (b[1] - c[1]), r = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = l - r, sum = std::abs(l) + std::abs(r);
  if (std::abs(det) > detail::kOrient2dBound * sum && sum > detail::kTiny) return (det > 0) - (det < 0);
  return detail::orient2d_exact(a, b, c);
}

// Sign of the 3D orientation: +1 if d lies strictly above the plane through the
// lifted points a, b, c when (a, b, c) is counterclockwise in xy, -1 below, 0 on it.
int orient3d(const double* a, const double* b, const double* c, const double* d);

// Unperturbed in-circle sign: +1 if d is strictly inside the circle through a, b, c
// (counterclockwise), 0 on it, -1 outside.
inline int in_circle_sign(const double* a, const double* b, const double* c, const double* d) {
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  const double det = alift * bc + blift * ca + clift * ab;
  const double perm = (std::abs(bdx * cdy) + std::abs(cdx * bdy)) * alift +
                      (std::abs(cdx * ady) + std::abs(adx * cdy)) * blift +
                      (std::abs(adx * bdy) + std::abs(bdx * ady)) * clift;
  if (std::abs(det) > detail::kInCircleBound * perm && perm > detail::kTiny) return (det > 0) - (det < 0);
  return detail::in_circle_exact(a, b, c, d);
}

// Is d strictly inside the circle through a, b, c (counterclockwise)? Points on the
// circle are decided by CGAL's symbolic perturbation (lexicographic xy order), the
// same one that makes the Delaunay triangulation unique; so this predicate never
// answers "on the circle" and agrees with every decision the triangulation made.
inline bool in_circle(const double* a, const double* b, const double* c, const double* d) {
  const int s = in_circle_sign(a, b, c, d);
  return s != 0 ? s > 0 : detail::in_circle_perturbed(a, b, c, d);
}

// Position of r against the circle with diameter pq: +1 inside, 0 on, -1 outside.
int diametral_sign(const double* p, const double* q, const double* r);

// Sign of the plane (xy) length of ab minus `length`, exact: -1, 0, +1. (Inline:
// a domain asks it of every triangle's edges, and the filter decides almost all.)
inline int compare_length(const double* a, const double* b, double length) {
  if (length == INFINITY) return -1;  // (coordinates are finite)
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  const double d2 = dx * dx + dy * dy, l2 = length * length;
  // d2 is within 4 eps of |ab|^2 (rounded differences, squares, sum), l2 within
  // one eps of length^2.
  const double diff = d2 - l2, sum = d2 + l2;
  if ((diff > 8 * detail::kEps * sum || -diff > 8 * detail::kEps * sum) && sum > detail::kTiny && sum < INFINITY)
    return diff > 0 ? 1 : -1;
  return detail::compare_length_exact(a, b, length);
}

// Which of two descents from v is steeper: the sign of (z_v - z_a) / |va| minus
// (z_v - z_b) / |vb| (plane lengths), exact: -1, 0, +1. a and b must be strictly
// lower than v and at other (x, y): both slopes are then positive, so their order
// is that of their squares, and the sign is that of
//   D = dz_a^2 |vb|^2 - dz_b^2 |va|^2   (dz = z_v - z, |.|^2 = dx^2 + dy^2),
// a polynomial in the coordinates, with no root or division. (Inline: drainage
// asks it of every edge, and the filter decides almost all.)
inline int compare_descents(const double* v, const double* a, const double* b) {
  const double dza = v[2] - a[2], dzb = v[2] - b[2];
  const double xa = v[0] - a[0], ya = v[1] - a[1], xb = v[0] - b[0], yb = v[1] - b[1];
  const double pa = dza * dza * (xb * xb + yb * yb), pb = dzb * dzb * (xa * xa + ya * ya);
  // With u = 2^-53 each rounded difference is within u, a square within 3u, a
  // length^2 within 4u, so each product is within 8u (plus O(u^2)) of its exact
  // value and D within u |pa - pb| + 8.1u (pa + pb) < 12u sum: the sign of diff
  // is exact when |diff| exceeds that.
  const double diff = pa - pb, sum = pa + pb;
  if ((diff > 12 * detail::kEps * sum || -diff > 12 * detail::kEps * sum) && sum > detail::kTiny && sum < INFINITY)
    return diff > 0 ? 1 : -1;
  return detail::compare_descents_exact(v, a, b);
}

// Lexicographic xy order, exact: -1, 0, +1.
int compare_xy(const double* a, const double* b);

}  // namespace hodt
