#include "hodt/format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace hodt {

std::string format_number(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Infinity" : "-Infinity";
  if (v == 0) return "0";
  if (v == std::floor(v) && std::fabs(v) < 9007199254740992.0) {  // integers as integers
    char buf[24];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  // Shortest precision that round-trips (what JavaScript's Number#toString does).
  // A normal double v is within 2^-53 |v| of every decimal that reads back to it,
  // less than half a unit in its 15th digit (at least 5e-16 |v|): so when the
  // shortest such decimal has p <= 15 digits, v rounded to 15 digits is those p
  // digits and zeros, which %g drops. Trying 15, 16, 17 therefore prints what
  // trying every precision from 1 would, in at most three tries.
  char buf[40];
  for (int prec = std::fabs(v) >= 0x1p-1022 ? 15 : 1; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string json_number(double v) {
  if (!std::isfinite(v)) throw std::logic_error("a measured value is " + format_number(v) + ": not a JSON number");
  return format_number(v);
}

std::string json_string(std::string_view text) {
  std::string s = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') s += '\\', s += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      s += buf;
    } else s += c;
  }
  return s + '"';
}

}  // namespace hodt
