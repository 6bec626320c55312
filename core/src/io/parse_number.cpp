#include "io/parse_number.hpp"

#include <fast_float/fast_float.h>

#include "containers/out_of_line.hpp"

namespace hodt {
namespace {

// fast_float's exact big-decimal fallback, rarely taken (Eisel-Lemire settles
// nearly every number), kept out of parse_double: inlined, it makes parse_double
// several times larger, and V8 runs a wasm function in its baseline tier until
// its optimising compile, which takes time proportional to the function's size,
// is done, so a large parse_double reads most of a file in baseline code. Called
// out of line (containers/out_of_line.hpp): Binaryen inlines any function called
// from one place, whatever its attributes.
const auto exact_fallback = [](fast_float::parsed_number_string& pns, fast_float::adjusted_mantissa am) noexcept {
  return fast_float::digit_comp<double>(pns, am);
};

// fast_float::from_chars_advanced for double, step by step as fast_float writes
// it (parse_number.h), with the fallback above out of line: the same steps in
// the same order, so the same double.
fast_float::from_chars_result from_chars_double(const char* first, const char* last, double& value,
                                                fast_float::parse_options options) noexcept {
  using namespace fast_float;
  using format = binary_format<double>;
  from_chars_result answer;
  if (first == last) {
    answer.ec = std::errc::invalid_argument;
    answer.ptr = first;
    return answer;
  }
  parsed_number_string pns = parse_number_string(first, last, options);
  if (!pns.valid) return detail::parse_infnan(first, last, value);
  answer.ec = std::errc();
  answer.ptr = pns.lastmatch;
  // Clinger's fast path, as fast_float takes it in either rounding mode.
  if (format::min_exponent_fast_path() <= pns.exponent && pns.exponent <= format::max_exponent_fast_path() &&
      !pns.too_many_digits) {
    if (detail::rounds_to_nearest()) {
      if (pns.mantissa <= format::max_mantissa_fast_path()) {
        value = double(pns.mantissa);
        if (pns.exponent < 0) value = value / format::exact_power_of_ten(-pns.exponent);
        else value = value * format::exact_power_of_ten(pns.exponent);
        if (pns.negative) value = -value;
        return answer;
      }
    } else if (pns.exponent >= 0 && pns.mantissa <= format::max_mantissa_fast_path(pns.exponent)) {
#if defined(__clang__)
      if (pns.mantissa == 0) {
        value = 0;
        return answer;
      }
#endif
      value = double(pns.mantissa) * format::exact_power_of_ten(pns.exponent);
      if (pns.negative) value = -value;
      return answer;
    }
  }
  adjusted_mantissa am = compute_float<format>(pns.exponent, pns.mantissa);
  if (pns.too_many_digits && am.power2 >= 0) {
    if (am != compute_float<format>(pns.exponent, pns.mantissa + 1)) am = compute_error<format>(pns.exponent, pns.mantissa);
  }
  if (am.power2 < 0) am = out_of_line(exact_fallback, pns, am);
  to_float(pns.negative, am, value);
  return answer;
}

}  // namespace

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
  const auto r = from_chars_double(tok.data(), end, out, options);
  // (out of range is not an error: 1e999 gives infinity, 1e-999 zero, as strtod)
  return r.ptr == end && (r.ec == std::errc() || r.ec == std::errc::result_out_of_range);
}

}  // namespace hodt
