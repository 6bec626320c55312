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
  char buf[40];
  for (int prec = 1; prec <= 17; ++prec) {
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
