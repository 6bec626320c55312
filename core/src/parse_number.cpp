#include "hodt/parse_number.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace hodt {

namespace {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// [+-]digits[.digits] whose digits, read as an integer, are at most 2^53 and with
// at most 22 after the point: m / 10^f rounds once, correctly. Else false.
bool parse_plain_decimal(std::string_view s, double& out) {
  size_t i = 0;
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
  uint64_t m = 0;
  int after_point = 0;
  bool digits = false, point = false;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (c >= '0' && c <= '9') {
      digits = true;
      m = m * 10 + static_cast<uint64_t>(c - '0');
      if (m > (uint64_t(1) << 53)) return false;
      if (point && ++after_point > 22) return false;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      return false;
    }
  }
  if (!digits) return false;
  const double v = static_cast<double>(m) / kPow10[after_point];
  out = negative ? -v : v;
  return true;
}

}  // namespace

bool parse_double(std::string_view tok, double& out) {
  if (tok.empty()) return false;
  if (parse_plain_decimal(tok, out)) return true;
  // strtod rounds correctly however many digits there are (glibc natively, musl
  // in wasm), and takes a leading '+' and exponents such as 1E+03.
  char small[72];
  std::string large;
  const char* buf = small;
  if (tok.size() < sizeof small) {
    std::copy(tok.begin(), tok.end(), small);
    small[tok.size()] = 0;
  } else {
    large.assign(tok);
    buf = large.c_str();
  }
  char* end = nullptr;
  out = std::strtod(buf, &end);
  return end == buf + tok.size();
}

}  // namespace hodt
