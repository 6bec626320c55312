// The 2x2 determinant behind every measured area and normal component: twice
// the signed area of a triangle projected on two coordinates, with its sign
// exact and its magnitude within 4 ulps (the plain float formula can be off by
// any factor, or of the wrong sign, when its two products cancel: a point
// within rounding of a segment). Needs coordinates in the range of points.hpp
// (no product underflows or overflows) and no fused multiply-add (the build sets
// -ffp-contract=off; wasm has no fma anyway).
#pragma once
#include <cmath>

namespace hodt {

// A difference of two coordinates, b - a = d + e exactly: d rounded, e its
// rounding error (Knuth's two-diff). e is 0 when the difference is exact, as it
// mostly is between nearby points (Sterbenz).
struct Difference {
  double d, e;
};
inline Difference difference(double b, double a) {
  const double d = b - a, bv = b - d, av = d + bv;
  return {d, (b - av) + (bv - a)};
}

namespace detail {
// a b - fl(a b) exactly (Dekker's product, no fma), if no partial product
// underflows: the coordinate range keeps every product at least 2^-404.
inline double product_tail(double a, double b, double ab) {
  const double ca = 134217729.0 * a, cb = 134217729.0 * b;  // split at 2^27 + 1
  const double ahi = ca - (ca - a), bhi = cb - (cb - b), alo = a - ahi, blo = b - bhi;
  return alo * blo - (((ab - ahi * bhi) - alo * bhi) - ahi * blo);
}

// The exact determinant as an expansion (Shewchuk), within one ulp: for slivers
// (accurate_det.cpp).
double exact_det(Difference ux, Difference uy, Difference vx, Difference vy);

// The determinant when its two products p and q cancel much (S = |p| + |q| >
// 2 |det|, the same sign): exactly, det = (p - q) + (p's rounding error - q's) +
// E1 + E2, with E1 and E2 the first- and second-order terms of the differences'
// errors. p - q and the products' errors are exact (Knuth, Dekker); e1 is E1
// within 6u^2 S (u = 2^-53), and summing the small terms adds at most about
// 14u^2 S: with |det| >= 2^-48 S (= 32u S) that is below 0.7u |det|, and the
// last sum rounds by u |det|: within 2u |det| in all. Thinner (a sliver): the
// exact expansion.
inline double cancelling_det(Difference ux, Difference uy, Difference vx, Difference vy, double p, double q,
                             double e1) {
  const double t = p - q, tv = p - t, tail = (p - (t + tv)) + (tv - q);  // p - q = t + tail (Knuth)
  const double small = ((tail + (product_tail(ux.d, vy.d, p) - product_tail(uy.d, vx.d, q))) + e1) +
                       (ux.e * vy.e - uy.e * vx.e);
  const double det = t + small;
  if (std::abs(det) >= 0x1p-48 * (std::abs(p) + std::abs(q))) return det;
  return exact_det(ux, uy, vx, vy);
}
}  // namespace detail

// Rotates a triangle to start at its middle corner in lexicographic xy order.
// Then the value of accurate_det no longer depends on the rotation the caller
// was given, and its two products have opposite signs (no cancellation) in the
// xy plane whenever the corner in the middle along x is not also the one in the
// middle along y: two triangles in three. (Branch-free: mispredicted branches
// would cost more than the arithmetic.)
inline void middle_first(const double*& a, const double*& b, const double*& c) {
  auto less = [](const double* p, const double* q) { return (p[0] < q[0]) | ((p[0] == q[0]) & (p[1] < q[1])); };
  const bool ba = less(b, a), cb = less(c, b), ac = less(a, c);
  // The middle one: a if b < a < c or c < a < b, else b if ..., else c.
  const int m = (ba != ac) * (1 + (ba != cb));
  const double* const t[5] = {a, b, c, a, b};
  a = t[m], b = t[m + 1], c = t[m + 2];
}

// (b_i - a_i)(c_j - a_j) - (b_j - a_j)(c_i - a_i).
inline double accurate_det(const double* a, const double* b, const double* c, int i = 0, int j = 1) {
  const Difference ux = difference(b[i], a[i]), uy = difference(b[j], a[j]);
  const Difference vx = difference(c[i], a[i]), vy = difference(c[j], a[j]);
  // The products of the rounded differences plus the first-order terms of their
  // errors, e (zero when the differences are exact). With u = 2^-53 and S = |p| +
  // |q| the error is at most u S (products) + u |det| (p - q) + u |det| (+ e, if
  // not 0) + O(u^2 S): within 4u |det| when S <= 3 |det| (e = 0) or S <= 2 |det|,
  // so the sign is exact too. That holds whenever p and q have opposite signs
  // (S = |det|), and for most other triangles.
  const double p = ux.d * vy.d, q = uy.d * vx.d;
  const double e = (ux.d * vy.e + ux.e * vy.d) - (uy.d * vx.e + uy.e * vx.d);
  const double det = (p - q) + e;
  if (std::abs(det) * (e == 0 ? 3 : 2) >= std::abs(p) + std::abs(q)) return det;
  return detail::cancelling_det(ux, uy, vx, vy, p, q, e);
}

}  // namespace hodt
