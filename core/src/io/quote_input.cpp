#include "io/quote_input.hpp"

#include <cstdint>

namespace hodt {
namespace {

const char* kHex = "0123456789abcdef";

// The length of the well-formed UTF-8 sequence at s[i] and its code point
// (shortest form, no surrogates, at most U+10FFFF); 0 if there is none.
size_t utf8_at(std::string_view s, size_t i, uint32_t& c) {
  const auto b = static_cast<unsigned char>(s[i]);
  const size_t n = b >= 0xF0 && b < 0xF5 ? 4 : b >= 0xE0 ? (b < 0xF0 ? 3 : 0) : b >= 0xC2 ? 2 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  c = b & (0x7F >> n);
  for (size_t k = 1; k < n; ++k) {
    const auto t = static_cast<unsigned char>(s[i + k]);
    if ((t & 0xC0) != 0x80) return 0;
    c = c << 6 | (t & 0x3F);
  }
  const uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (c < least[n] || c > 0x10FFFF || (c >= 0xD800 && c < 0xE000)) return 0;
  return n;
}

// Printed as itself: C1 controls, line and paragraph separators, the byte order
// mark and the bidirectional overrides and isolates are not.
bool printable(uint32_t c) {
  return c >= 0xA0 && c != 0x2028 && c != 0x2029 && c != 0xFEFF && !(c >= 0x202A && c <= 0x202E) &&
         !(c >= 0x2066 && c <= 0x2069) && !(c >= 0x200E && c <= 0x200F);
}

// Appends the escaped form of the character at s[i]; returns its length in s.
size_t append_escaped(std::string& out, std::string_view s, size_t i) {
  const auto b = static_cast<unsigned char>(s[i]);
  if (b >= 0x20 && b < 0x7F) return out += static_cast<char>(b), 1;
  if (b == '\n') return out += "\\n", 1;
  if (b == '\r') return out += "\\r", 1;
  if (b == '\t') return out += "\\t", 1;
  uint32_t c = 0;
  const size_t n = b >= 0x80 ? utf8_at(s, i, c) : 0;
  if (n > 0 && printable(c)) return out.append(s.substr(i, n)), n;
  if (n > 0) {
    out += "\\u";
    for (int shift = 12; shift >= 0; shift -= 4) out += kHex[(c >> shift) & 0xF];
    return n;
  }
  out += "\\x";
  out += kHex[b >> 4];
  out += kHex[b & 0xF];
  return 1;
}

}  // namespace

std::string quote_input(std::string_view text, size_t max_chars) {
  std::string out = "'";
  size_t i = 0, shown = 0;
  while (i < text.size() && shown < max_chars) i += append_escaped(out, text, i), ++shown;
  if (i < text.size()) out += "...";
  return out + "'";
}

std::string escape_input(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size();) i += append_escaped(out, text, i);
  return out;
}

}  // namespace hodt
