#include "terrain/crs.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace hodt {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

bool is_code(std::string_view s) {
  if (s.empty() || s.size() > 9) return false;
  for (const char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Printable ASCII on one line: WKT is ASCII, and what we write must stay valid
// in every output (JSON, PLY headers).
std::string one_line(std::string_view s) {
  std::string out;
  bool space = false;
  for (const char c : trim(s)) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isspace(u)) {
      space = true;
      continue;
    }
    if (space && !out.empty()) out += ' ';
    space = false;
    out += u >= 0x20 && u < 0x7f ? c : '?';
  }
  return out;
}

// The keywords a WKT coordinate system starts with: WKT1 (OGC 01-009, ESRI's .prj)
// and WKT2 (ISO 19162), long and short forms.
bool is_wkt_crs_keyword(const std::string& k) {
  static const char* const keywords[] = {
      "PROJCS",   "GEOGCS",        "GEOCCS",      "VERT_CS",       "COMPD_CS",      "LOCAL_CS",     "FITTED_CS",
      "PROJCRS",  "PROJECTEDCRS",  "GEOGCRS",     "GEOGRAPHICCRS", "GEODCRS",       "GEODETICCRS",  "VERTCRS",
      "VERTICALCRS", "COMPOUNDCRS", "ENGCRS",     "ENGINEERINGCRS", "BOUNDCRS",     "DERIVEDPROJCRS", "PARAMETRICCRS",
      "TIMECRS"};
  for (const char* w : keywords)
    if (k == w) return true;
  return false;
}

// An EPSG code as people write it: EPSG:N (any case, also EPSG::N), the OGC URN
// urn:ogc:def:crs:EPSG:[version]:N, the OGC URI .../def/crs/EPSG/0/N, or N alone.
std::optional<std::string> epsg_code(std::string_view text) {
  const std::string u = upper(text);
  std::string_view code;
  for (const char* prefix : {"EPSG::", "EPSG:", "HTTP://WWW.OPENGIS.NET/DEF/CRS/EPSG/0/", "HTTPS://WWW.OPENGIS.NET/DEF/CRS/EPSG/0/"})
    if (u.rfind(prefix, 0) == 0) {
      code = text.substr(std::string_view(prefix).size());
      break;
    }
  if (u.rfind("URN:OGC:DEF:CRS:EPSG:", 0) == 0) {
    code = text.substr(21);
    code = code.substr(code.find(':') == std::string_view::npos ? code.size() : code.find(':') + 1);  // (the version)
  }
  if (code.empty() && is_code(text)) code = text;
  if (!is_code(code) || code.find_first_not_of('0') == std::string_view::npos) return std::nullopt;
  return "EPSG:" + std::string(code.substr(code.find_first_not_of('0')));
}

// A PROJ string: +proj=NAME followed by +key or +key=value parameters, blank
// separated ("+proj=utm +zone=33 +datum=WGS84 +units=m +no_defs").
bool is_proj_string(std::string_view text) {
  bool proj = false;
  size_t i = 0;
  while (i < text.size()) {
    const size_t j = std::min(text.find_first_of(" \t", i), text.size());
    const std::string_view token = text.substr(i, j - i);
    if (token.size() < 2 || token[0] != '+') return false;
    const size_t eq = token.find('=');
    const std::string_view key = token.substr(1, eq == std::string_view::npos ? std::string_view::npos : eq - 1);
    if (key.empty()) return false;
    for (const char c : key)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    for (const char c : token)
      if (static_cast<unsigned char>(c) <= 0x20 || static_cast<unsigned char>(c) >= 0x7f) return false;
    if (key == "proj" && eq != std::string_view::npos && eq + 1 < token.size()) proj = true;
    i = text.find_first_not_of(" \t", j);
    if (i == std::string_view::npos) break;
  }
  return proj;
}

}  // namespace

std::optional<std::string> crs_of_wkt(std::string_view wkt) {
  if (wkt.rfind("\xEF\xBB\xBF", 0) == 0) wkt.remove_prefix(3);  // a byte order mark (Windows tools write one)
  wkt = trim(wkt);
  size_t i = 0;
  while (i < wkt.size() && (std::isalnum(static_cast<unsigned char>(wkt[i])) || wkt[i] == '_')) ++i;
  if (i == 0 || i >= wkt.size() || (wkt[i] != '[' && wkt[i] != '(') || !is_wkt_crs_keyword(upper(wkt.substr(0, i))))
    return std::nullopt;
  // Walk the brackets; the outermost CRS's own AUTHORITY/ID sits at depth 1.
  int depth = 0;
  bool quoted = false;
  size_t word = 0;  // start of the keyword before the next bracket
  std::optional<std::string> code;
  for (size_t p = 0; p < wkt.size(); ++p) {
    const char c = wkt[p];
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '[' || c == '(') {
      const std::string key = upper(trim(wkt.substr(word, p - word)));
      if (depth == 1 && (key == "AUTHORITY" || key == "ID")) {
        const size_t close = wkt.find_first_of("])", p);
        if (close == std::string_view::npos) return std::nullopt;
        const std::string_view args = wkt.substr(p + 1, close - p - 1);
        const size_t comma = args.find(',');
        if (comma != std::string_view::npos) {
          auto unquote = [](std::string_view a) {
            a = trim(a);
            if (a.size() >= 2 && a.front() == '"' && a.back() == '"') a = a.substr(1, a.size() - 2);
            return trim(a);
          };
          const std::string_view name = unquote(args.substr(0, comma));
          std::string_view number = unquote(args.substr(comma + 1));
          number = number.substr(0, number.find(','));  // (WKT2 may add a version)
          if (upper(name) == "EPSG" && is_code(trim(number))) code = "EPSG:" + std::string(trim(number));
        }
      }
      ++depth;
      word = p + 1;
    } else if (c == ']' || c == ')') {
      if (--depth < 0) return std::nullopt;
      word = p + 1;
    } else if (c == ',') word = p + 1;
  }
  if (depth != 0 || quoted) return std::nullopt;
  return code ? *code : one_line(wkt);
}

std::optional<std::string> crs_of_text(std::string_view text) {
  text = trim(text);
  if (text.empty() || text.size() > kMaxCrsChars) return std::nullopt;
  if (auto epsg = epsg_code(text)) return epsg;
  if (auto wkt = crs_of_wkt(text)) return wkt;
  if (is_proj_string(text)) return one_line(text);
  return std::nullopt;
}

std::string prj_path(const std::string& file) {
  const size_t slash = file.find_last_of("/\\");
  const size_t dot = file.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  return (has_ext ? file.substr(0, dot) : file) + ".prj";
}

}  // namespace hodt
