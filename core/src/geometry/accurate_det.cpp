// The exact expansion of accurate_det (accurate_det.hpp), after Shewchuk, "Adaptive
// precision floating-point arithmetic and fast robust geometric predicates"
// (1997): every product of the differences' parts is split into a rounded value
// and its exact error, and the terms are summed into an expansion (a sum of
// doubles with no rounding at all). Products are Dekker's (no fma: wasm has none).
#include "hodt/accurate_det.hpp"

namespace hodt {

namespace {

struct Split {
  double hi, lo;
};

// a + b = hi + lo exactly (Knuth).
Split two_sum(double a, double b) {
  const double x = a + b, bv = x - a, av = x - bv;
  return {x, (a - av) + (b - bv)};
}

// a b = hi + lo exactly (Dekker).
Split two_product(double a, double b) {
  const double x = a * b;
  return {x, detail::product_tail(a, b, x)};
}

// An expansion: nonoverlapping components, increasing magnitude, no zeros.
struct Expansion {
  double c[16];
  int n = 0;

  // Adds one double exactly (Shewchuk's Grow-Expansion with zero elimination).
  void add(double b) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const Split s = two_sum(b, c[i]);
      if (s.lo != 0) c[m++] = s.lo;
      b = s.hi;
    }
    if (b != 0) c[m++] = b;
    n = m;
  }

  // The sum, within one ulp: compressed (Shewchuk's Compress), the largest
  // component is within one ulp of the whole and the others are smaller than it.
  double value() const {
    if (n == 0) return 0;
    double g[16];
    int bottom = n - 1;
    double q = c[n - 1];
    for (int i = n - 2; i >= 0; --i) {
      const double sum = q + c[i], lo = c[i] - (sum - q);  // Fast-Two-Sum: |q| >= |c[i]|
      if (lo != 0) g[bottom--] = sum, q = lo;
      else q = sum;
    }
    g[bottom] = q;
    // Upwards: the smaller parts are carried into the next larger.
    double h = g[bottom], rest = 0;
    for (int i = bottom + 1; i < n; ++i) {
      const double sum = g[i] + h, lo = h - (sum - g[i]);
      rest += lo;  // below the final ulp: affects only the rounding
      h = sum;
    }
    return h + rest;
  }
};

}  // namespace

double detail::exact_det(Difference ux, Difference uy, Difference vx, Difference vy) {
  // (ux.d + ux.e)(vy.d + vy.e) - (uy.d + uy.e)(vx.d + vx.e), every part exact.
  Expansion sum;
  auto product = [&](double a, double b, double sign) {
    if (a == 0 || b == 0) return;
    const Split p = two_product(a, b);
    sum.add(sign * p.lo);
    sum.add(sign * p.hi);
  };
  // Smallest terms first: the expansion then grows in order of magnitude.
  product(ux.e, vy.e, 1), product(uy.e, vx.e, -1);
  product(ux.d, vy.e, 1), product(ux.e, vy.d, 1);
  product(uy.d, vx.e, -1), product(uy.e, vx.d, -1);
  product(ux.d, vy.d, 1), product(uy.d, vx.d, -1);
  return sum.value();
}

}  // namespace hodt
