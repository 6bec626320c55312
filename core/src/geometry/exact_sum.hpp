// The sum of doubles, exact until one final rounding: a long accumulator
// (Kulisch). Every finite double is an integer multiple of 2^-1074 below 2^1024,
// so any sum of them is an integer (in units of 2^-1074) of a little over 2098
// bits; it is kept exactly in 32-bit digits held in 64-bit cells, so that a
// digit's carry can wait for 2^30 additions. value() rounds the exact sum once,
// to nearest with ties to even: the result is the correctly rounded sum, so it
// does not depend on the order of the terms, and it costs a few operations a
// term (no sorting).
#pragma once
#include <array>
#include <cstdint>

namespace hodt {

class ExactSum {
 public:
  void add(double x);
  ExactSum& operator+=(double x) {
    add(x);
    return *this;
  }
  // The exact sum rounded to nearest (ties to even); +0 for no terms or an exact
  // zero; infinite if it overflows; the IEEE sum of the terms if one is infinite
  // or NaN.
  double value() const;

 private:
  // Digits of 32 bits from 2^-1074 up: a double spans at most 3 of the 64 that
  // hold its 2098 bits, and 4 more take the carries of up to 2^128 terms.
  static constexpr int kCells = 68;
  static constexpr uint32_t kCarryEvery = 1u << 30;  // cells stay below 2^62
  void propagate();
  std::array<int64_t, kCells> cell_{};
  uint32_t since_carry_ = 0;
  double special_ = 0;  // the IEEE sum of the non-finite terms
  bool has_special_ = false;
};

}  // namespace hodt
