#include "geometry/exact_sum.hpp"

#include <bit>
#include <cmath>
#include <cstring>

namespace hodt {

void ExactSum::add(double x) {
  uint64_t bits;  // (no std::bit_cast in every standard library this builds with)
  std::memcpy(&bits, &x, sizeof bits);
  const uint32_t biased = static_cast<uint32_t>(bits >> 52) & 0x7ff;
  if (biased == 0x7ff) {  // infinite or NaN: no exact value to keep
    special_ += x;
    has_special_ = true;
    return;
  }
  const uint64_t fraction = bits & ((uint64_t{1} << 52) - 1);
  // |x| = m 2^(shift - 1074): subnormals have biased exponent 0 and no hidden bit.
  const uint64_t m = biased == 0 ? fraction : fraction | uint64_t{1} << 52;
  if (m == 0) return;
  const uint32_t shift = biased == 0 ? 0 : biased - 1;
  const uint32_t at = shift / 32, off = shift % 32;
  // m 2^off has at most 84 bits: digits at, at + 1 and at + 2.
  const uint64_t low = static_cast<uint32_t>(m << off);
  const uint64_t high = off == 0 ? m >> 32 : m >> (32 - off);
  const int64_t d0 = static_cast<int64_t>(low), d1 = static_cast<int64_t>(high & 0xffffffff),
                d2 = static_cast<int64_t>(high >> 32);
  if (bits >> 63) {
    cell_[at] -= d0, cell_[at + 1] -= d1, cell_[at + 2] -= d2;
  } else {
    cell_[at] += d0, cell_[at + 1] += d1, cell_[at + 2] += d2;
  }
  if (++since_carry_ == kCarryEvery) propagate();
}

// Each cell's digit into [0, 2^32), its carry into the next; the top cell keeps
// the sign of the whole sum.
void ExactSum::propagate() {
  for (int i = 0; i + 1 < kCells; ++i) {
    const int64_t carry = cell_[i] >> 32;  // floor division by 2^32
    cell_[i] -= carry * (int64_t{1} << 32);
    cell_[i + 1] += carry;
  }
  since_carry_ = 0;
}

double ExactSum::value() const {
  if (has_special_) return special_;
  ExactSum s = *this;
  s.propagate();
  // A negative sum: negate it (every cell, then the digits again) and round its
  // magnitude; rounding to nearest is symmetric.
  const bool negative = s.cell_[kCells - 1] < 0;
  if (negative) {
    for (int64_t& c : s.cell_) c = -c;
    s.propagate();
  }
  const auto& d = s.cell_;  // digits, all in [0, 2^32)
  int top = kCells - 1;
  while (top >= 0 && d[top] == 0) --top;
  if (top < 0) return 0.0;
  // The sum has `bits` bits; take its leading 64 (window from bit `from`) and
  // whether any bit below them is set.
  const int bits = 32 * top + std::bit_width(static_cast<uint64_t>(d[top]));
  const int from = bits - 64;
  auto digit = [&](int i) { return i >= 0 && i < kCells ? static_cast<uint64_t>(d[i]) : uint64_t{0}; };
  uint64_t lead;
  bool sticky = false;
  if (from <= 0) {  // the whole sum fits in 64 bits
    lead = (digit(1) << 32 | digit(0)) << -from;
  } else {
    const int i = from / 32, off = from % 32;
    // bits [from, from + 64) lie in digits i .. i + 2
    lead = (digit(i) >> off) | (digit(i + 1) << (32 - off));
    if (off != 0) lead |= digit(i + 2) << (64 - off);
    sticky = off != 0 && (digit(i) & ((uint64_t{1} << off) - 1)) != 0;
    for (int j = 0; j < i && !sticky; ++j) sticky = d[j] != 0;
  }
  // 53 bits kept, 11 below them decide, with the sticky bit, the rounding.
  uint64_t keep = lead >> 11;
  const uint64_t rest = lead & 0x7ff, half = 0x400;
  if (rest > half || (rest == half && (sticky || (keep & 1)))) ++keep;  // (2^53 is exact too)
  // keep 2^(from + 11) in units of 2^-1074: exact unless it overflows (then
  // infinite) since keep has at most 53 significant bits and the scale is
  // within the doubles' range or above it.
  const double magnitude = std::ldexp(static_cast<double>(keep), from + 11 - 1074);
  return negative ? -magnitude : magnitude;
}

}  // namespace hodt
