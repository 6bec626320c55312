// Text that is not what it seems: decimal commas under ';' (European
// spreadsheets), lines written with another delimiter or decimal mark than the
// rest of the file, more columns than x, y, z with no header naming them, and
// file content that would break a one-line message.
#include <doctest/doctest.h>

#include <string>

#include "hodt/error.hpp"
#include "hodt/read_points.hpp"
#include "io/quote_input.hpp"

using namespace hodt;

namespace {
std::string read_error(const std::string& text, const std::string& name = "f.csv") {
  try {
    read_points(text, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
bool one_printable_line(const std::string& s) {
  for (const char c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
  return true;
}
}  // namespace

TEST_CASE("a semicolon file with decimal commas reads with ',' as the decimal mark") {
  const std::vector<double> want = {1.5, 2.25, 3, 0.125, -4, 10, 7, 8.75, 1e3};
  CHECK(read_points("1,5;2,25;3\n0,125;-4;10\n7;8,75;1E3\n", "eu.csv").xyz == want);
  CHECK(read_points("X;Y;Z\r\n1,5 ; 2,25 ; 3\r\n0,125;-4;10\r\n7;8,75;1E3\r\n", "eu.csv").xyz == want);
  CHECK(read_points("\"x\";\"y\";\"z\"\n\"1,5\";\"2,25\";\"3\"\n0,125;-4;10\n7;8,75;1E3\n", "eu.csv").xyz == want);
  // The same numbers with a decimal point under ';', and blank separated with decimal commas.
  CHECK(read_points("1.5;2.25;3\n0.125;-4;10\n7;8.75;1E3\n", "p.csv").xyz == want);
  CHECK(read_points("1,5\t2,25\t3\n0,125\t-4\t10\n7\t8,75\t1E3\n", "eu.tsv").xyz == want);
  CHECK(read_points("x y z\n1,5 2,25 3\n0,125 -4 10\n7 8,75 1E3\n", "eu.txt").xyz == want);
  // Under ',' spreadsheets (LibreOffice, pandas' to_csv(decimal=',')) quote decimal commas.
  CHECK(read_points("\"1,5\",\"2,25\",3\n\"0,125\",-4,10\n7,\"8,75\",1E3\n", "q.csv").xyz == want);
  CHECK(read_points("\"x\",\"y\",\"z\"\n\"1,5\" , \"2,25\",\"3\"\n\"0,125\",-4,10\n7,\"8,75\",1E3\n", "q.csv").xyz == want);
  // A 17-digit decimal with a comma is the double the point gives.
  CHECK(read_points("0,1000000000000000055511151231257827;1;2\n0;0;0\n1;0;0\n", "eu.csv").xyz[0] == 0.1);
}

TEST_CASE("a file mixing delimiters or decimal marks is refused in one line naming them") {
  CHECK(read_error("1;2;3\n4,5,6\n") == "f.csv: line 2: expected 3 numbers x y z separated by ';' as on line 1, got 1 field '4,5,6'");
  CHECK(read_error("x,y,z\n1,2,3\n4;5;6\n") ==
        "f.csv: line 3: expected 3 numbers x y z separated by ',' as on line 1, got 1 field '4;5;6'");
  CHECK(read_error("x,y,z\n1 2 3\n") == "f.csv: line 2: expected 3 numbers x y z separated by ',' as on line 1, got 1 field '1 2 3'");
  CHECK(read_error("1 2 3\n4;5;6\n") ==
        "f.csv: line 2: expected 3 numbers x y z separated by spaces or tabs as on line 1, got 1 field '4;5;6'");
  CHECK(read_error("1;2;3\n1,5;2,5;3\n0.5;1;2\n") ==
        "f.csv: line 3: x is '0.5' with a decimal point, but line 2 has decimal commas: one decimal mark per file");
  CHECK(read_error("1.5;2;3\n1,5;2;3\n") ==
        "f.csv: line 2: x is '1,5' with a decimal comma, but line 1 has decimal points: one decimal mark per file");
  CHECK(read_error("\"1,5\",2,3\n0.5,1,2\n") ==
        "f.csv: line 2: x is '0.5' with a decimal point, but line 1 has decimal commas: one decimal mark per file");
  // Digit grouping, and a comma that is no decimal mark, name the delimiter.
  CHECK(read_error("1.234,5;2;3\n") == "f.csv: line 1: x is '1.234,5', not a number (fields separated by ';' as on line 1)");
  CHECK(read_error("1, 2 3\n") == "f.csv: line 1: x is '1,', not a number (fields separated by spaces or tabs as on line 1)");
}

TEST_CASE("more columns than x, y, z with no header naming them are refused; a header names them") {
  CHECK(read_error("0,1.5,2.5,3\n1,2.5,1.5,4\n2,0,0,1\n") ==
        "f.csv: line 1: 4 columns (',') and no header naming x, y and z; add a first line naming the columns, such as "
        "'id,x,y,z' (or easting, northing, elevation)");
  CHECK(read_error("a b c d\n0 1 2 3\n") ==
        "f.csv: line 2: 4 columns (spaces or tabs) and no header naming x, y and z; add a first line naming the columns, "
        "such as 'id x y z' (or easting, northing, elevation)");
  CHECK(read_points("id,x,y,z\n0,1.5,2.5,3\n1,2.5,1.5,4\n2,0,0,1\n", "id.csv").xyz ==
        std::vector<double>{1.5, 2.5, 3, 2.5, 1.5, 4, 0, 0, 1});
  CHECK(read_points("Easting;Northing;Elevation;Intensity\n1;2;3;9\n4;5;6;9\n7;8;0,5;9\n", "e.csv").xyz ==
        std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 0.5});
  // A trailing delimiter (spreadsheets write one) is no column; an unnamed header of three still reads.
  CHECK(read_points("1,2,3,\n4,5,6,\n0,1,0,\n", "t.csv").xyz.size() == 9);
  CHECK(read_points("a,b,c\n1,2,3\n4,5,6\n0,1,0\n", "t.csv").xyz.size() == 9);
}

TEST_CASE("messages quoting file content are one printable line") {
  const std::string key = read_error("[{\"x\": 1, \"y\n\ny\n\": 2, \"z\": 3}]", "k.json");
  CHECK(key == "k.json: line 1: point 0: unexpected key 'y\\n\\ny\\n', expected x, y, z");
  CHECK(read_error("0 0 0\n1 \x01\x1b[2J\x7f 1\n0 1 2\n") == "f.csv: line 2: y is '\\x01\\x1b[2J\\x7f', not a number");
  CHECK(read_error("0 0 0\n1 \xff\xfe\xc3\xa9\xe2\x80\xae 1\n") == "f.csv: line 2: y is '\\xff\\xfe\xc3\xa9\\u202e', not a number");
  CHECK(read_error("[[0, 0, 1],\r\n\t[1, 0]]", "a.json") == "a.json: line 2: point 1: expected [x, y, z] with 3 numbers, found ']]'");
  CHECK(read_error("[1\n,\n2]", "a.json") == "a.json: line 1: point 0: expected [x, y, z], found '1\\n,\\n2]'");
  CHECK(read_error("ncols 3\nnrows\x07 x\n", "g.asc") == "g.asc: line 2: nrows\\x07 is 'x', not a number");
  CHECK(read_error("0 0 0\n1 x 1\n", "bad\nname.csv") == "bad\\nname.csv: line 2: y is 'x', not a number");
  // Whatever the bytes, one line.
  std::string junk;
  for (int b = 1; b < 256; ++b) junk += static_cast<char>(b);
  for (const std::string& text : {"0 0 0\n1 " + junk + " 1\n", "[{\"" + junk + "\": 1}]", "[[1, " + junk + "]]", junk})
    CHECK(one_printable_line(read_error(text)));
}

TEST_CASE("quote_input escapes what would not print and keeps what does") {
  CHECK(quote_input("plain text") == "'plain text'");
  CHECK(quote_input("a\r\nb\tc") == "'a\\r\\nb\\tc'");
  CHECK(quote_input("caf\xc3\xa9 \xe6\x97\xa5 \xf0\x9f\x97\xbb") == "'caf\xc3\xa9 \xe6\x97\xa5 \xf0\x9f\x97\xbb'");
  CHECK(quote_input("\xc2\x85\xe2\x80\xa8\xef\xbb\xbf") == "'\\u0085\\u2028\\ufeff'");  // NEL, line separator, BOM
  CHECK(quote_input("\xc0\xaf\xed\xa0\x80\xf4\x90\x80\x80\xe2\x82") == "'\\xc0\\xaf\\xed\\xa0\\x80\\xf4\\x90\\x80\\x80\\xe2\\x82'");
  CHECK(quote_input(std::string(50, 'a')) == "'" + std::string(40, 'a') + "...'");
  CHECK(quote_input("abcdef", 3) == "'abc...'");
  CHECK(escape_input("C:\\data\\dem\n.csv") == "C:\\data\\dem\\n.csv");
  CHECK(escape_input(escape_input("x\x01y")) == escape_input("x\x01y"));
}
