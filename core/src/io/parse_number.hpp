// A number token of a text file to the double nearest its decimal value.
#pragma once
#include <string_view>

namespace hodt {

// Parses the whole token as a decimal: [+-]digits[.digits][(e|E)[+-]digits],
// "inf", "infinity" and "nan" in any case (the readers then name them as not
// finite); false for anything else (hex floats and surrounding spaces too).
// Correctly rounded for any number of digits, as strtod: fast_float's
// from_chars (Eisel-Lemire with an exact big-decimal fallback), the same in wasm
// as natively. decimal_mark is the character between the integer and the
// fraction: '.' or, for files written with decimal commas, ','.
bool parse_double(std::string_view token, double& out, char decimal_mark = '.');

}  // namespace hodt
