// A number token of a text file to the double nearest its decimal value.
#pragma once
#include <string_view>

namespace hodt {

// Parses the whole token; false if it is not a number. Correctly rounded for any
// number of digits, a leading '+' and exponents (1E+03) included, the same as
// strtod; plain decimals of up to 2^53 in their digits and at most 22 after the
// point take a fast exact path (Clinger: both operands of one IEEE division are
// exact, so its rounding is the decimal's).
bool parse_double(std::string_view token, double& out);

}  // namespace hodt
