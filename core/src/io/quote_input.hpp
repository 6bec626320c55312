// Text from a file or the command line, quoted in a one-line message.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace hodt {

// 'text' in single quotes, on one printable line: at most max_chars characters
// of it (then "..."), with line breaks, tabs and other control characters,
// bytes that are not UTF-8, and the Unicode line separators and direction
// overrides written as escapes (\n, \r, \t, \xNN, \uNNNN), so that the message
// cannot break a terminal or a log. Printable text is kept as it is, a backslash
// too (Windows paths stay readable); so escaping twice changes nothing.
std::string quote_input(std::string_view text, size_t max_chars = 40);

// The same escapes without quotes or shortening: for names (files, keys) that
// a message spells out whole.
std::string escape_input(std::string_view text);

}  // namespace hodt
