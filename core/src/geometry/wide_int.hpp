// Signed 256-bit integers, just enough for exact predicates on integer
// coordinates of up to 62 bits: sums of products of two 125-bit numbers (an
// in-circle determinant is below 2^252). Two's complement in four 64-bit words,
// least significant first; no allocation, unlike an arbitrary-precision type.
#pragma once
#include <cstdint>

namespace hodt {

using Int128 = __int128;
using Uint128 = unsigned __int128;

struct Int256 {
  uint64_t w[4] = {0, 0, 0, 0};

  static Int256 of(Int128 v) {
    Int256 r;
    r.w[0] = static_cast<uint64_t>(v);
    r.w[1] = static_cast<uint64_t>(static_cast<Uint128>(v) >> 64);
    r.w[2] = r.w[3] = v < 0 ? ~uint64_t{0} : 0;
    return r;
  }
  // a * b exactly, for |a|, |b| < 2^127.
  static Int256 product(Int128 a, Int128 b) {
    const bool negative = (a < 0) != (b < 0);
    const Uint128 x = a < 0 ? -static_cast<Uint128>(a) : static_cast<Uint128>(a);
    const Uint128 y = b < 0 ? -static_cast<Uint128>(b) : static_cast<Uint128>(b);
    const uint64_t x0 = static_cast<uint64_t>(x), x1 = static_cast<uint64_t>(x >> 64);
    const uint64_t y0 = static_cast<uint64_t>(y), y1 = static_cast<uint64_t>(y >> 64);
    const Uint128 p00 = static_cast<Uint128>(x0) * y0, p01 = static_cast<Uint128>(x0) * y1;
    const Uint128 p10 = static_cast<Uint128>(x1) * y0, p11 = static_cast<Uint128>(x1) * y1;
    // Column sums with carries: (p11 << 128) + ((p01 + p10) << 64) + p00.
    const Uint128 mid = (p00 >> 64) + static_cast<uint64_t>(p01) + static_cast<uint64_t>(p10);
    const Uint128 high = (mid >> 64) + (p01 >> 64) + (p10 >> 64) + static_cast<uint64_t>(p11);
    Int256 r;
    r.w[0] = static_cast<uint64_t>(p00);
    r.w[1] = static_cast<uint64_t>(mid);
    r.w[2] = static_cast<uint64_t>(high);
    r.w[3] = static_cast<uint64_t>(high >> 64) + static_cast<uint64_t>(p11 >> 64);
    return negative ? r.negated() : r;
  }
  Int256 negated() const {
    Int256 r;
    uint64_t carry = 1;
    for (int i = 0; i < 4; ++i) {
      const uint64_t v = ~w[i] + carry;
      carry = carry && v == 0;
      r.w[i] = v;
    }
    return r;
  }
  Int256 operator+(const Int256& o) const {
    Int256 r;
    uint64_t carry = 0;
    for (int i = 0; i < 4; ++i) {
      const Uint128 s = static_cast<Uint128>(w[i]) + o.w[i] + carry;
      r.w[i] = static_cast<uint64_t>(s);
      carry = static_cast<uint64_t>(s >> 64);
    }
    return r;
  }
  int sign() const {
    if (w[3] >> 63) return -1;
    return (w[0] | w[1] | w[2] | w[3]) != 0;
  }
};

}  // namespace hodt
