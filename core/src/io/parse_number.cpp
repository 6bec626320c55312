#include "io/parse_number.hpp"

#include <fast_float/fast_float.h>

namespace hodt {

bool parse_double(std::string_view tok, double& out, char decimal_mark) {
  // from_chars follows C++17 and refuses a leading '+', which spreadsheets and
  // strtod accept: it is taken off here, once ("+-1" and "++1" stay refused).
  if (!tok.empty() && tok.front() == '+') {
    tok.remove_prefix(1);
    if (!tok.empty() && (tok.front() == '+' || tok.front() == '-')) return false;
  }
  if (tok.empty()) return false;
  const char* end = tok.data() + tok.size();
  const fast_float::parse_options options(fast_float::chars_format::general, decimal_mark);
  const auto r = fast_float::from_chars_advanced(tok.data(), end, out, options);
  // (out of range is not an error: 1e999 gives infinity, 1e-999 zero, as strtod)
  return r.ptr == end && (r.ec == std::errc() || r.ec == std::errc::result_out_of_range);
}

}  // namespace hodt
