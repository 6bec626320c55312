#include "hodt/read_points.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>

#include "hodt/domain.hpp"
#include "hodt/error.hpp"
#include "containers/out_of_line.hpp"
#include "io/parse_number.hpp"
#include "io/quote_input.hpp"
#include "io/text_encoding.hpp"

namespace hodt {
namespace {

struct Reader {
  const std::string& name;
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(name + ": line " + std::to_string(line) + ": " + what);
  }
  // The same with the message made by `message()`, out of line: the checks on
  // every number and line then stay small (the wasm build's baseline code runs
  // a function until its optimising compile, whose time grows with its size, is
  // done). Through out_of_line, since Binaryen inlines a function called from
  // one place whatever its attributes.
  template <class Message>
  [[noreturn, gnu::noinline, gnu::cold]] void fail_with(int line, Message message) const {
    const auto raise = [](const Reader& r, int at, Message& m) { r.fail(at, m()); };
    out_of_line(raise, *this, line, message);
    __builtin_unreachable();
  }
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A value quoted for a one-line message: up to the end of its line, at most 40
// characters, escaped.
std::string shorten(std::string_view s) { return quote_input(s.substr(0, s.find_first_of("\r\n"))); }

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim_blanks(std::string_view f) {
  while (!f.empty() && blank(f.front())) f.remove_prefix(1);
  while (!f.empty() && blank(f.back())) f.remove_suffix(1);
  return f;
}

std::string_view unquote(std::string_view f) {
  if (f.size() >= 2 && (f.front() == '"' || f.front() == '\'') && f.back() == f.front()) f = f.substr(1, f.size() - 2);
  return f;
}

// The fields of a line: split at each delimiter (',' or ';', blanks around a field
// trimmed, a field in double quotes read to its closing quote, delimiters inside
// included, as spreadsheets quote "1,5" under ','; trailing empty fields dropped as
// a spreadsheet's trailing delimiter) or, for ' ', at runs of spaces and tabs;
// into `out`, reused from line to line so that a line costs no allocation.
void split_fields(std::string_view line, char delimiter, std::vector<std::string_view>& out) {
  out.clear();
  if (delimiter == ' ') {
    for (size_t i = 0; i < line.size();) {
      while (i < line.size() && blank(line[i])) ++i;
      size_t j = i;
      while (j < line.size() && !blank(line[j])) ++j;
      if (j > i) out.push_back(unquote(line.substr(i, j - i)));
      i = j;
    }
    return;
  }
  for (size_t i = 0;;) {
    size_t from = i;
    while (from < line.size() && blank(line[from])) ++from;
    if (from < line.size() && line[from] == '"') from = std::min(line.find('"', from + 1), line.size());
    const size_t j = std::min(line.find(delimiter, from), line.size());
    out.push_back(unquote(trim_blanks(line.substr(i, j - i))));
    if (j == line.size()) break;
    i = j + 1;
  }
  while (!out.empty() && out.back().empty()) out.pop_back();
}
std::vector<std::string_view> split_fields(std::string_view line, char delimiter) {
  std::vector<std::string_view> out;
  split_fields(line, delimiter, out);
  return out;
}

// The first LF or CR in [i, end), or end: eight bytes per step. For a word w and
// a byte c, (x - ones) & ~x & highs with x = w ^ (c * ones) sets the high bit of
// every byte of w equal to c and may set more only above such a byte (a borrow
// runs upwards), so its lowest set bit is exact.
inline const char* find_line_end(const char* i, const char* end) {
  if constexpr (std::endian::native == std::endian::little) {
    constexpr uint64_t ones = 0x0101010101010101u, highs = 0x8080808080808080u;
    for (; end - i >= 8; i += 8) {
      uint64_t w;
      std::memcpy(&w, i, 8);
      const uint64_t lf = w ^ (ones * '\n'), cr = w ^ (ones * '\r');
      const uint64_t hit = (((lf - ones) & ~lf) | ((cr - ones) & ~cr)) & highs;
      if (hit) return i + std::countr_zero(hit) / 8;
    }
  }
  while (i != end && *i != '\n' && *i != '\r') ++i;
  return i;
}

// Lines end with LF (Unix), CR LF (Windows) or a lone CR (classic Mac, some exports).
// `f` is called per line out of line (containers/out_of_line.hpp), so that V8
// moves it to its optimising tier after the first lines.
template <class F>
void for_each_line(std::string_view text, F f) {
  if (text.empty()) return f(1, text);
  const char* const end = text.data() + text.size();
  int line = 0;
  for (const char* i = text.data();;) {
    const char* const j = find_line_end(i, end);
    out_of_line(f, ++line, std::string_view(i, static_cast<size_t>(j - i)));
    if (j == end) break;
    i = j + (*j == '\r' && j + 1 != end && j[1] == '\n' ? 2 : 1);
  }
}

bool blank_or_comment(std::string_view s) {
  for (const char c : s)
    if (!blank(c)) return c == '#';
  return true;
}

void check_finite(const Reader& r, int line, const char* axis, double v, std::string_view tok) {
  if (!std::isfinite(v))
    r.fail_with(line, [&] { return std::string(axis) + " is " + shorten(tok) + ", expected a finite number"; });
}

// How a text file separates its fields and writes its decimals: decided once, from
// its first lines, so that every line is read alike and a line written otherwise
// is refused rather than read as other numbers.
struct TextLayout {
  char delimiter = 0;     // ',', ';' or ' ' (runs of spaces and tabs)
  int delimiter_line = 0;
  char decimal_mark = 0;  // '.' or ',' once a number has shown one
  int decimal_line = 0;

  // From the first line that is not blank or a comment. A ';' delimits (European
  // spreadsheets write "1,5;2,25;3": decimal commas), else a ','; but numbers
  // holding blanks between commas ("1,5 2,25 3", "1,5<TAB>2,25") are blank
  // separated with decimal commas.
  void choose(std::string_view line, int at, bool header) {
    delimiter_line = at;
    if (line.find(';') != std::string_view::npos) delimiter = ';';
    else if (line.find(',') == std::string_view::npos) delimiter = ' ';
    else {
      delimiter = ',';
      if (!header)
        for (const std::string_view f : split_fields(line, ','))
          if (f.find_first_of(" \t") != std::string_view::npos) delimiter = ' ';
    }
  }
  std::string delimiter_name() const { return delimiter == ' ' ? "spaces or tabs" : std::string("'") + delimiter + "'"; }
  std::string as_on_first_line() const {
    return "separated by " + delimiter_name() + " as on line " + std::to_string(delimiter_line);
  }
};

// The header's columns for x, y and z (or easting/northing/elevation, lon/lat/height).
std::optional<std::array<int, 3>> named_columns(const std::vector<std::string_view>& fields) {
  std::map<std::string, int> at;
  for (size_t k = 0; k < fields.size(); ++k) at.emplace(lower(fields[k]), static_cast<int>(k));
  const char* names[3][5] = {{"x", "lon", "longitude", "easting", "east"},
                             {"y", "lat", "latitude", "northing", "north"},
                             {"z", "elevation", "height", "elev", "h"}};
  std::array<int, 3> found;
  for (int a = 0; a < 3; ++a) {
    found[a] = -1;
    for (const char* nm : names[a])
      if (at.count(nm)) {
        found[a] = at[nm];
        break;
      }
    if (found[a] < 0) return std::nullopt;
  }
  return found;
}

// One coordinate: with the file's decimal mark, decided by the first number that
// has one (a ',' in a field of a ',' file was quoted: a decimal comma too).
double text_number(const Reader& r, TextLayout& layout, int line, const char* axis, std::string_view tok) {
  // The first ',' and whether a '.' appears, in one pass (a token is short: a
  // loop costs less than a call of memchr per character sought).
  size_t c = std::string_view::npos;
  bool point = false;
  for (size_t k = 0; k < tok.size(); ++k) {
    if (tok[k] == ',' && c == std::string_view::npos) c = k;
    point |= tok[k] == '.';
  }
  const bool comma = c != std::string_view::npos;
  char mark = layout.decimal_mark ? layout.decimal_mark : '.';
  if (comma != point) {
    mark = comma ? ',' : '.';
    if (layout.decimal_mark && layout.decimal_mark != mark)
      r.fail_with(line, [&] {
        return std::string(axis) + " is " + shorten(tok) + " with a decimal " + (comma ? "comma" : "point") +
               ", but line " + std::to_string(layout.decimal_line) + " has decimal " + (comma ? "points" : "commas") +
               ": one decimal mark per file";
      });
  }
  double v;
  // A decimal comma sits between digits: "1," or ",5" next to a blank is a delimiter misplaced.
  const bool digits_around =
      !comma || (c > 0 && c + 1 < tok.size() && std::isdigit(static_cast<unsigned char>(tok[c - 1])) &&
                 std::isdigit(static_cast<unsigned char>(tok[c + 1])));
  if (!digits_around || !parse_double(tok, v, mark))
    r.fail_with(line, [&] {
      return std::string(axis) + " is " + shorten(tok) + ", not a number" +
             (comma || tok.find(';') != std::string_view::npos ? " (fields " + layout.as_on_first_line() + ")" : "");
    });
  if (comma != point && !layout.decimal_mark) {
    layout.decimal_mark = mark;
    layout.decimal_line = line;
  }
  check_finite(r, line, axis, v, tok);
  return v;
}

ParsedPoints read_text(std::string_view text, const Reader& r) {
  ParsedPoints out;
  std::array<int, 3> cols = {0, 1, 2};
  std::optional<std::array<int, 3>> named;
  TextLayout layout;
  bool first = true;
  size_t want = 3;
  std::vector<std::string_view> fields;
  // The first line read decides the layout; true if it is a header (out of line
  // below: it runs once, and inlined it would make the function every line runs
  // larger).
  const auto header_line = [&](int line, std::string_view s) {
    // A header: its first field is not a number (whatever the delimiter and decimal mark).
    double v0;
    const std::string_view s0 = trim_blanks(s);
    const size_t close = s0.substr(0, 1) == "\"" ? s0.find('"', 1) : std::string_view::npos;
    const std::string_view f0 = close != std::string_view::npos ? s0.substr(1, close - 1) : s0.substr(0, s0.find_first_of(",; \t"));
    const bool header = !parse_double(f0, v0) && !parse_double(f0, v0, ',');
    layout.choose(s, line, header);
    if (header) {
      named = named_columns(split_fields(s, layout.delimiter));
      if (named) {
        cols = *named;
        want = static_cast<size_t>(*std::max_element(cols.begin(), cols.end())) + 1;
      }
    }
    return header;
  };
  for_each_line(text, [&](int line, std::string_view s) {
    if (blank_or_comment(s)) return;
    if (first) {
      first = false;
      if (out_of_line(header_line, line, s)) return;
    }
    split_fields(s, layout.delimiter, fields);
    if (fields.size() < want) r.fail_with(line, [&] {
      std::string what = want == 3 ? "expected 3 numbers x y z"
                                   : "expected " + std::to_string(want) + " fields, up to the columns named x, y and z";
      // (a line written with another delimiter than the file's, or without the file's)
      const bool other = s.find_first_of(layout.delimiter == ',' ? ";" : layout.delimiter == ';' ? "," : ",;") !=
                         std::string_view::npos;
      if (other || (layout.delimiter != ' ' && s.find(layout.delimiter) == std::string_view::npos))
        what += ' ' + layout.as_on_first_line();
      what += ", got " + std::to_string(fields.size()) + (fields.size() == 1 ? " field " : " fields ");
      return what + shorten(s);
    });
    // More columns than x, y and z, and no header to say which they are: an id
    // column first or intensities after are equally likely, so none is guessed.
    if (!named && fields.size() > 3) r.fail_with(line, [&] {
      const std::string d = layout.delimiter == ' ' ? " " : std::string(1, layout.delimiter);
      return std::to_string(fields.size()) + " columns (" + layout.delimiter_name() +
             ") and no header naming x, y and z; add a first line naming the columns, such as 'id" + d + "x" + d + "y" +
             d + "z' (or easting, northing, elevation)";
    });
    static const char* axis[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) out.xyz.push_back(text_number(r, layout, line, axis[a], fields[cols[a]]));
    out.lines.push_back(line);
  });
  return out;
}

// A small JSON reader for [[x, y, z], ...] and [{"x":..,"y":..,"z":..}, ...].
struct JsonReader {
  std::string_view s;
  const Reader& r;
  size_t i = 0;
  int line = 1;
  void ws() {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) {
      // LF, CR LF and a lone CR each end one line
      if (s[i] == '\n' || (s[i] == '\r' && (i + 1 == s.size() || s[i + 1] != '\n'))) ++line;
      ++i;
    }
  }
  [[noreturn]] void fail(const std::string& what) { r.fail(line, what); }
  char peek() { ws(); return i < s.size() ? s[i] : '\0'; }
  void expect(char c, const char* what) {
    if (peek() != c) fail(std::string("expected ") + what + ", found " + near());
    ++i;
  }
  std::string near() {
    if (i >= s.size()) return "end of file";
    return quote_input(s.substr(i, 20), 20);
  }
  double number(const char* axis) {
    ws();
    size_t j = i;
    while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '-' ||
                            s[j] == '+' || s[j] == '.'))
      ++j;
    double v;
    const std::string_view tok = s.substr(i, j - i);
    if (!parse_double(tok, v) || tok.empty())
      fail(std::string(axis) + " is " + (tok.empty() ? near() : shorten(tok)) + ", not a number");
    check_finite(r, line, axis, v, tok);
    i = j;
    return v;
  }
  std::string key() {
    expect('"', "a quoted key");
    size_t j = s.find('"', i);
    if (j == std::string_view::npos) fail("unterminated string");
    std::string k(s.substr(i, j - i));
    i = j + 1;
    return lower(k);
  }
};

ParsedPoints read_json(std::string_view text, const Reader& r) {
  ParsedPoints out;
  JsonReader j{text, r};
  j.expect('[', "'[' starting the list of points");
  static const char* axis[3] = {"x", "y", "z"};
  if (j.peek() == ']') { ++j.i; }
  else for (;;) {
    j.peek();  // skip to the point so that its line is the one recorded
    const int line = j.line;
    const size_t index = out.lines.size();
    const std::string where = "point " + std::to_string(index) + ": ";
    if (j.peek() == '[') {
      ++j.i;
      for (int a = 0; a < 3; ++a) {
        if (a) {
          if (j.peek() != ',') j.fail(where + "expected [x, y, z] with 3 numbers, found " + j.near());
          ++j.i;
        }
        out.xyz.push_back(j.number(axis[a]));
      }
      if (j.peek() != ']') j.fail(where + "expected [x, y, z] with 3 numbers, found " + j.near());
      ++j.i;
    } else if (j.peek() == '{') {
      ++j.i;
      double v[3];
      bool have[3] = {false, false, false};
      if (j.peek() != '}') for (;;) {
        const std::string k = j.key();
        j.expect(':', "':'");
        const int a = k == "x" ? 0 : k == "y" ? 1 : k == "z" ? 2 : -1;
        if (a < 0) j.fail(where + "unexpected key " + quote_input(k) + ", expected x, y, z");
        v[a] = j.number(axis[a]);
        have[a] = true;
        if (j.peek() == ',') { ++j.i; continue; }
        break;
      }
      j.expect('}', "'}'");
      for (int a = 0; a < 3; ++a)
        if (!have[a]) j.fail(where + "missing " + axis[a]);
      out.xyz.insert(out.xyz.end(), v, v + 3);
    } else {
      j.fail(where + "expected [x, y, z], found " + j.near());
    }
    out.lines.push_back(line);
    if (j.peek() == ',') { ++j.i; continue; }
    j.expect(']', "',' or ']'");
    break;
  }
  if (j.peek() != '\0') j.fail("unexpected text after the list of points: " + j.near());
  return out;
}

ParsedPoints read_ascii_grid(std::string_view text, const Reader& r) {
  std::map<std::string, double> header;
  std::map<std::string, std::string> raw;
  ParsedPoints out;
  long ncols = -1, nrows = -1;
  double x0 = 0, y0 = 0, cell = 0, nodata = std::nan("");
  bool has_nodata = false;
  long row = 0;
  int last_line = 0;
  std::vector<std::string_view> fields;
  for_each_line(text, [&](int line, std::string_view s) {
    if (blank_or_comment(s)) return;
    last_line = line;
    split_fields(s, ' ', fields);
    double v;
    if (row == 0 && out.lines.empty() && !parse_double(fields[0], v)) {
      if (fields.size() != 2) r.fail(line, "expected 'key value' in the grid header, got " + shorten(s));
      const std::string k = lower(fields[0]);
      if (!parse_double(fields[1], v) || !std::isfinite(v))
        r.fail(line, escape_input(k) + " is " + shorten(fields[1]) + ", not a number");
      header[k] = v;
      return;
    }
    if (ncols < 0) {
      for (const char* k : {"ncols", "nrows", "cellsize"})
        if (!header.count(k)) r.fail(line, std::string("grid header is missing ") + k);
      if (!(header.count("xllcorner") || header.count("xllcenter")) ||
          !(header.count("yllcorner") || header.count("yllcenter")))
        r.fail(line, "grid header needs xllcorner/xllcenter and yllcorner/yllcenter");
      const double nc = header["ncols"], nr = header["nrows"];
      if (nc < 1 || nr < 1 || nc != std::floor(nc) || nr != std::floor(nr) || nc * nr > 5e7)
        r.fail(line, "ncols and nrows must be positive integers (at most 5e7 cells)");
      ncols = static_cast<long>(nc);
      nrows = static_cast<long>(nr);
      cell = header["cellsize"];
      if (!(cell > 0)) r.fail(line, "cellsize must be positive");
      const bool corner = header.count("xllcorner") > 0;
      x0 = (corner ? header["xllcorner"] : header["xllcenter"]) + (corner ? cell / 2 : 0);
      y0 = (header.count("yllcorner") ? header["yllcorner"] + cell / 2 : header["yllcenter"]);
      if (header.count("nodata_value")) { nodata = header["nodata_value"]; has_nodata = true; }
    }
    if (row >= nrows) r.fail(line, "more than nrows = " + std::to_string(nrows) + " rows of values");
    if (static_cast<long>(fields.size()) != ncols)
      r.fail(line, "expected ncols = " + std::to_string(ncols) + " values, got " +
                       std::to_string(fields.size()));
    for (long c = 0; c < ncols; ++c) {
      if (!parse_double(fields[c], v))
        r.fail(line, "value " + std::to_string(c + 1) + " is " + shorten(fields[c]) + ", not a number");
      if (has_nodata && v == nodata) {
        ++out.nodata_cells;
        continue;
      }
      check_finite(r, line, "z", v, fields[c]);
      out.xyz.push_back(x0 + c * cell);
      out.xyz.push_back(y0 + (nrows - 1 - row) * cell);  // the first row is the northernmost
      out.xyz.push_back(v);
      out.lines.push_back(line);
    }
    ++row;
  });
  if (ncols < 0) r.fail(last_line, "grid has a header but no values");
  if (out.nodata_cells > 0) out.max_edge = kRasterMaxEdgeCells * cell;
  if (row != nrows)
    r.fail(last_line, "expected nrows = " + std::to_string(nrows) + " rows of values, got " + std::to_string(row));
  return out;
}

// Binary files named by their first bytes: read as text they give a misleading
// "line 2: x is ..." and garbage on the terminal.
std::optional<std::string> binary_format(std::string_view b) {
  auto starts = [&](std::string_view magic) { return b.substr(0, magic.size()) == magic; };
  if (starts(std::string_view("II*\0", 4)) || starts(std::string_view("MM\0*", 4)) || starts(std::string_view("II+\0", 4)) ||
      starts(std::string_view("MM\0+", 4)))
    return "a TIFF/GeoTIFF raster, not text; the npm CLI (npx hodt) and hodt/loaders read GeoTIFF DEMs";
  if (starts("LASF")) return "a LAS/LAZ point cloud, not text; the npm CLI (npx hodt) and hodt/loaders read LAS and LAZ";
  if (starts("PK\x03\x04")) return "a zip archive, not text; extract it first";
  if (starts("\x1f\x8b")) return "a gzip file, not text; decompress it first";
  if (starts("\x89PNG")) return "a PNG image, not elevation data";
  if (starts("\xff\xd8\xff")) return "a JPEG image, not elevation data";
  if (starts("%PDF")) return "a PDF document, not elevation data";
  if (starts("\x7f" "ELF")) return "an executable, not elevation data";
  return std::nullopt;
}

}  // namespace

ParsedPoints read_points(std::string_view text, const std::string& file_name, PointFormat format) {
  const std::string name = escape_input(file_name);  // (a name may hold anything a file system allows)
  if (const auto binary = binary_format(text)) throw InputError(name + ": " + *binary);
  const Reader r{name};
  // A byte order mark would otherwise make the first line look like a header.
  const std::optional<std::string> decoded = utf8_from_utf16(text);
  text = skip_utf8_bom(decoded ? std::string_view(*decoded) : text);
  if (format == PointFormat::Auto) {
    const size_t k = text.find_first_not_of(" \t\r\n");
    if (k == std::string_view::npos) throw InputError(name + ": the file is empty");
    if (text[k] == '[') format = PointFormat::Json;
    else if (lower(text.substr(k, 5)) == "ncols") format = PointFormat::AsciiGrid;
    else format = PointFormat::Text;
  }
  ParsedPoints out = format == PointFormat::Json        ? read_json(text, r)
                     : format == PointFormat::AsciiGrid ? read_ascii_grid(text, r)
                                                        : read_text(text, r);
  if (out.lines.empty()) throw InputError(name + ": no points found");
  return out;
}

}  // namespace hodt
