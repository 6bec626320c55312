// Point files as people have them: byte order marks, UTF-16, every line ending,
// long decimals, a leading '+', exponents. Each must read to the same doubles.
#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "hodt/error.hpp"
#include "hodt/read_points.hpp"
#include "generators.hpp"
#include "io/parse_number.hpp"

using namespace hodt;

namespace {
const std::vector<double> kPoints = {0, 0, 1, 1, 0, 2, 0, 1, 3};

std::vector<double> xyz_of(const std::string& text, const std::string& name = "f.csv") {
  return read_points(text, name).xyz;
}

// UTF-16 with its byte order mark, from ASCII text.
std::string utf16(const std::string& ascii, bool little_endian) {
  std::string out = little_endian ? "\xFF\xFE" : "\xFE\xFF";
  for (char c : ascii) {
    if (little_endian) out += c, out += '\0';
    else out += '\0', out += c;
  }
  return out;
}

uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
}  // namespace

TEST_CASE("a UTF-8 byte order mark does not turn the first point into a header") {
  const ParsedPoints p = read_points("\xEF\xBB\xBF" "0 0 1\n1 0 2\n0 1 3\n", "bom.txt");
  CHECK(p.xyz == kPoints);
  CHECK(p.lines == std::vector<int>{1, 2, 3});
  // A header after the mark is still a header.
  CHECK(xyz_of("\xEF\xBB\xBF" "x,y,z\n0,0,1\n1,0,2\n0,1,3\n") == kPoints);
  CHECK(xyz_of("\xEF\xBB\xBF" "[[0, 0, 1], [1, 0, 2], [0, 1, 3]]", "bom.json") == kPoints);
  CHECK(read_points("\xEF\xBB\xBF" "ncols 2\nnrows 1\nxllcenter 0\nyllcenter 0\ncellsize 1\n1 2\n", "bom.asc").xyz ==
        std::vector<double>{0, 0, 1, 1, 0, 2});
  CHECK_THROWS_WITH_AS(read_points("\xEF\xBB\xBF", "bom.csv"), "bom.csv: the file is empty", InputError);
}

TEST_CASE("UTF-16 files (Windows' 'Unicode') read like their UTF-8 text") {
  for (bool le : {true, false}) {
    CAPTURE(le);
    CHECK(xyz_of(utf16("x;y;z\r\n0;0;1\r\n1;0;2\r\n0;1;3\r\n", le)) == kPoints);
    CHECK(xyz_of(utf16("[[0,0,1],[1,0,2],[0,1,3]]", le), "u.json") == kPoints);
  }
  // A header with non-ASCII names (U+00F6, and U+1D465 as a surrogate pair) is
  // still a header.
  std::string text = "\xFF\xFE";
  for (char16_t c : std::u16string(u"H\u00F6he \U0001D465 y\n0 0 1\n1 0 2\n0 1 3\n"))
    text += static_cast<char>(c & 0xFF), text += static_cast<char>(c >> 8);
  CHECK(xyz_of(text) == kPoints);
}

TEST_CASE("LF, CR LF and lone CR line endings, mixed too, count lines the same") {
  for (const char* eol : {"\n", "\r\n", "\r"}) {
    CAPTURE(std::string(eol).size());
    const std::string e = eol;
    const ParsedPoints p = read_points("x y z" + e + "0 0 1" + e + e + "1 0 2" + e + "0 1 3" + e, "f.txt");
    CHECK(p.xyz == kPoints);
    CHECK(p.lines == std::vector<int>{2, 4, 5});
    CHECK(xyz_of("[[0, 0, 1]," + e + "[1, 0, 2]," + e + "[0, 1, 3]]", "f.json") == kPoints);
    CHECK(read_points("ncols 2" + e + "nrows 1" + e + "xllcenter 0" + e + "yllcenter 0" + e + "cellsize 1" + e + "1 2" + e,
                      "f.asc").xyz == std::vector<double>{0, 0, 1, 1, 0, 2});
    // Errors name the same line whatever the ending.
    CHECK_THROWS_WITH_AS(read_points("0 0 1" + e + "1 0 2" + e + "0 x 3" + e, "f.txt"),
                         "f.txt: line 3: y is 'x', not a number", InputError);
    CHECK_THROWS_WITH_AS(read_points("[[0, 0, 1]," + e + "[1, 0]]", "f.json"),
                         "f.json: line 2: point 1: expected [x, y, z] with 3 numbers, found ']]'", InputError);
  }
  CHECK(read_points("0 0 1\r1 0 2\r\n0 1 3\n", "mixed.txt").lines == std::vector<int>{1, 2, 3});
}

TEST_CASE("line ends found a word at a time: every ending at every offset in a word") {
  // Lines of every length from 5 to 40 characters (numbers padded with blanks or
  // zeros), each ending in LF, CR LF or CR, some blank or a comment, so that an
  // ending falls at each of the eight places in a word and next to another.
  const char* eols[3] = {"\n", "\r\n", "\r"};
  std::string text;
  std::vector<double> want;
  std::vector<int> lines;
  int line = 0;
  for (int len = 5; len <= 40; ++len)
    for (int k = 0; k < 3; ++k) {
      ++line;
      if ((len + k) % 7 == 0) {
        text += std::string(static_cast<size_t>(len % 3), ' ') + (len % 2 ? "# note" : "") + eols[k];
        continue;
      }
      const std::string x = std::to_string(line), body = x + " 0" + std::string(static_cast<size_t>(len), '0') + " 2";
      text += body + std::string(static_cast<size_t>(len % 5), '\t') + eols[k];
      want.insert(want.end(), {static_cast<double>(line), 0, 2});
      lines.push_back(line);
    }
  const ParsedPoints p = read_points(text, "ends.txt");
  CHECK(p.xyz == want);
  CHECK(p.lines == lines);
  // The last line without an ending, of each length.
  for (int len = 1; len <= 17; ++len) {
    CAPTURE(len);
    const std::string last = "3 4 " + std::string(static_cast<size_t>(len), '5');
    CHECK(read_points("1 2 3\r\n" + last, "end.txt").lines == std::vector<int>{1, 2});
  }
}

TEST_CASE("long decimals are read correctly rounded") {
  // Exactly the double 0.06699443374662295, with zeros up to 36 characters.
  CHECK(xyz_of("0.0669944337466229500000000000000000 1 2\n1 0 0\n0 1 0\n")[0] == 0.06699443374662295);
  // 2^53 + 1 is halfway between two doubles: it rounds to even, but any nonzero
  // digit however far out decides it upwards.
  CHECK(bits(xyz_of("9007199254740993 0 0\n0 1 0\n1 1 0\n")[0]) == bits(9007199254740992.0));
  CHECK(bits(xyz_of("9007199254740993.000000000000000000000000000000000000000000000000000000000000001 0 0\n0 1 0\n1 1 0\n")[0]) ==
        bits(9007199254740994.0));
  // The exact decimal value of the double nearest 0.1 (55 significant digits).
  CHECK(xyz_of("0.1000000000000000055511151231257827021181583404541015625,0,0\n0,1,0\n1,1,0\n")[0] == 0.1);
  // UTM-like coordinates with more digits than a double holds.
  CHECK(xyz_of("731012.345678912345678912345678 5501234.5 12.75\n0 1 0\n1 1 0\n")[0] == 731012.3456789124);  // Python: float(text)
}

TEST_CASE("a leading plus and exponents in any spelling") {
  const std::vector<double> want = {1000, 1000, 1000, -1500, 0.025, 1, 0, 1, 3};
  CHECK(xyz_of("1e3 1E+03 +1000\n-1.5e3 +2.5E-2 +1\n+0 1 3\n") == want);
  CHECK(xyz_of("1e3,1E+03,+1000\n-1.5e3,+2.5E-2,+1\n+0,1,3\n") == want);
  CHECK(xyz_of("[[1e3, 1E+03, +1000], [-1.5e3, +2.5E-2, +1], [+0, 1, 3]]", "e.json") == want);
  CHECK(xyz_of("[{\"x\": 1e3, \"y\": 1E+03, \"z\": +1000}, {\"x\": -1.5e3, \"y\": +2.5E-2, \"z\": +1}, "
               "{\"x\": +0, \"y\": 1, \"z\": 3}]", "e.json") == want);
  // The first line is data, not a header, when it starts with a signed number.
  CHECK(read_points("+1 +2 +3\n0 0 0\n1 0 0\n", "plus.txt").lines == std::vector<int>{1, 2, 3});
  CHECK(read_points("ncols 2\nnrows 1\nxllcenter +1E+3\nyllcenter -2e1\ncellsize 5E-1\n+1 2e0\n", "e.asc").xyz ==
        std::vector<double>{1000, -20, 1, 1000.5, -20, 2});
}
