// The long accumulator against exact rational arithmetic: its value is the exact
// sum correctly rounded (nearest, ties to even), whatever the order of the terms,
// on random terms of every magnitude and sign, cancellations, subnormals, ties
// and overflow.
#include <doctest/doctest.h>

#include <algorithm>
#include <boost/multiprecision/cpp_int.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "geometry/exact_sum.hpp"

using namespace hodt;
using Rational = boost::multiprecision::cpp_rational;

namespace {

uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// A finite double as an exact rational: m 2^e.
Rational exact(double v) {
  int e;
  const double f = std::frexp(v, &e);  // v = f 2^e, 0.5 <= |f| < 1
  const auto m = static_cast<int64_t>(std::ldexp(f, 53));
  e -= 53;
  Rational r = m;
  boost::multiprecision::cpp_int p = 1;
  p <<= std::abs(e);
  return e >= 0 ? Rational(r * p) : Rational(r / p);
}

double sum_of(const std::vector<double>& v) {
  ExactSum s;
  for (double x : v) s.add(x);
  return s.value();
}

// r is the correctly rounded value of the exact sum s: no double is nearer, and
// on a tie r's last bit is even.
void check_rounded(const std::vector<double>& terms, double r) {
  Rational s = 0;
  for (double x : terms) s += exact(x);
  REQUIRE(std::isfinite(r));
  const double up = std::nextafter(r, INFINITY), down = std::nextafter(r, -INFINITY);
  const Rational err = abs(s - exact(r));
  const Rational up_err = std::isfinite(up) ? Rational(abs(s - exact(up))) : err + 1;
  const Rational down_err = std::isfinite(down) ? Rational(abs(s - exact(down))) : err + 1;
  CHECK(err <= up_err);
  CHECK(err <= down_err);
  if (err == up_err || err == down_err) CHECK((bits(r) & 1) == 0);
  if (s == 0) CHECK(bits(r) == bits(0.0));
}

}  // namespace

TEST_CASE("exact sum: the correctly rounded sum of random terms, in any order") {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-1074, 1000), count(0, 60), kind(0, 5);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<double> v(count(rng));
    const int k = kind(rng);
    for (double& x : v) {
      switch (k) {
        case 0: x = std::ldexp(unit(rng), exponent(rng) / 16); break;        // near 1
        case 1: x = std::ldexp(unit(rng), exponent(rng)); break;             // any magnitude
        case 2: x = std::abs(std::ldexp(unit(rng), exponent(rng) / 64)); break;  // lengths
        case 3: x = std::ldexp(unit(rng), -1074 + exponent(rng) % 60 + 60);  // subnormal, smallest normals
                if (std::abs(x) < std::numeric_limits<double>::denorm_min()) x = 0; break;
        case 4: x = std::ldexp(std::round(unit(rng) * 8), exponent(rng) / 32); break;  // ties, exact zeros
        default: x = std::ldexp(unit(rng), 1000 + exponent(rng) % 23); break;  // near the top
      }
    }
    // cancellation: the negated terms, and one more
    if (trial % 7 == 0) {
      const size_t n = v.size();
      for (size_t i = 0; i < n; ++i) v.push_back(-v[i]);
      v.push_back(std::ldexp(unit(rng), exponent(rng) / 8));
    }
    CAPTURE(trial);
    CAPTURE(k);
    const double r = sum_of(v);
    bool overflow = false;
    {
      Rational s = 0;
      for (double x : v) s += exact(x);
      overflow = abs(s) >= exact(std::numeric_limits<double>::max()) * 2;
    }
    if (!overflow) check_rounded(v, r);
    std::shuffle(v.begin(), v.end(), rng);
    CHECK(bits(sum_of(v)) == bits(r));
    std::reverse(v.begin(), v.end());
    CHECK(bits(sum_of(v)) == bits(r));
  }
}

TEST_CASE("exact sum: edge cases") {
  CHECK(bits(sum_of({})) == bits(0.0));
  CHECK(bits(sum_of({-0.0})) == bits(0.0));
  CHECK(sum_of({1e308, 1e308}) == INFINITY);
  CHECK(sum_of({-1e308, -1e308}) == -INFINITY);
  CHECK(sum_of({1e308, 1e308, -1e308}) == 1e308);  // no overflow on the way
  CHECK(sum_of({1e100, 1.0, -1e100}) == 1.0);
  CHECK(sum_of({0.1, 0.2}) == 0.30000000000000004);
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(sum_of({tiny, tiny, tiny}) == 3 * tiny);
  CHECK(sum_of({1.0, std::ldexp(1.0, -53)}) == 1.0);                                   // tie: to even
  CHECK(sum_of({1.0, std::ldexp(1.0, -53), std::ldexp(1.0, -1074)}) == std::nextafter(1.0, 2));  // past the tie
  CHECK(sum_of({std::nextafter(1.0, 2), std::ldexp(1.0, -53)}) == std::nextafter(std::nextafter(1.0, 2), 2));
  CHECK(std::isnan(sum_of({INFINITY, -INFINITY, 1.0})));
  CHECK(sum_of({INFINITY, 1.0}) == INFINITY);
  // many terms: the carries
  ExactSum s;
  for (int i = 0; i < 3000000; ++i) s.add(0.1);
  Rational want = exact(0.1) * 3000000;
  const double r = s.value();
  CHECK(abs(want - exact(r)) <= abs(want - exact(std::nextafter(r, 0))));
  CHECK(abs(want - exact(r)) <= abs(want - exact(std::nextafter(r, 1e300))));
}
