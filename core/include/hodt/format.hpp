// Shortest round-trip text of a double, as JavaScript prints it (JSON, messages).
#pragma once
#include <string>
#include <string_view>

namespace hodt {
std::string format_number(double v);
// The same for a JSON document, which cannot hold Infinity or NaN. Valid input
// never makes a measure non-finite (the coordinate range of points.hpp), so one
// is a bug: std::logic_error, not a number no JSON parser reads.
std::string json_number(double v);
// A JSON string literal of UTF-8 text: quoted, with quotes, backslashes and
// control characters escaped.
std::string json_string(std::string_view text);
}
