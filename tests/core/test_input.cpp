#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "hodt/error.hpp"
#include "hodt/points.hpp"
#include "hodt/read_points.hpp"

using namespace hodt;

static std::string error_of(const std::vector<double>& xyz, Dedupe d = Dedupe::Error) {
  try {
    validate_points(xyz, d);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

static std::string read_error(const std::string& text, const std::string& name = "f.csv") {
  try {
    read_points(text, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_CASE("validation names the index and the coordinate") {
  CHECK(error_of({0, 0, 0, 1, 0, 0, 0, 1, NAN}) == "point 2: z is NaN, expected a finite number");
  CHECK(error_of({0, 0, 0, INFINITY, 0, 0, 0, 1, 0}) == "point 1: x is Infinity, expected a finite number");
  CHECK(error_of({0, 0, 0, 1, 0}).find("multiple of 3") != std::string::npos);
  CHECK(error_of({0, 0, 0, 1, 0, 0}) == "need at least 3 distinct points, got 2");
  CHECK(error_of({0, 0, 0, 1, 1, 0, 2, 2, 0, 3, 3, 1}) ==
        "all 4 points are collinear: a terrain needs points spanning an area");
}

TEST_CASE("duplicates: an error naming both indices, or dropped with dedupe first") {
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 5, 5, 1, 0, 1, 0, 1, 0, 7};
  CHECK(error_of(p).rfind("point 1 and point 4 have the same (x, y) = (1, 0)", 0) == 0);
  const TerrainPoints t = validate_points(p, Dedupe::KeepFirst);
  CHECK(t.input_index == std::vector<uint32_t>{0, 1, 2, 3});
  CHECK(t.xyz[5] == 0);  // the first of the duplicates is kept (z = 0, not 7)
  // Three equal points: the first is kept.
  const TerrainPoints u = validate_points({2, 2, 9, 0, 0, 0, 2, 2, 8, 1, 0, 0, 2, 2, 7}, Dedupe::KeepFirst);
  CHECK(u.input_index == std::vector<uint32_t>{0, 1, 3});
  // Several groups: the one with the smallest (x, y) is named, with its two
  // earliest points, whatever order they are found in.
  CHECK(error_of({9, 9, 0, 0, 8, 0, 9, 9, 1, 5, 0, 0, 0, 8, 2, 0, 8, 3, 5, 0, 4}).rfind(
            "point 1 and point 4 have the same (x, y) = (0, 8)", 0) == 0);
  // The spatial order keeps the same points.
  const TerrainPoints s = validate_points(p, Dedupe::KeepFirst, {}, PointOrder::Spatial);
  std::vector<uint32_t> kept = s.input_index;
  std::sort(kept.begin(), kept.end());
  CHECK(kept == t.input_index);
}

TEST_CASE("text files: separators, header, comments") {
  const ParsedPoints a = read_points("x,y,z\n0,0,1\n1,0,2\n\n# comment\n0, 1 ,3,\n", "a.csv");
  CHECK(a.xyz == std::vector<double>{0, 0, 1, 1, 0, 2, 0, 1, 3});
  CHECK(a.lines == std::vector<int>{2, 3, 6});
  const ParsedPoints b = read_points("0 0 1\r\n1\t0\t2\r\n0   1 3", "b.txt");
  CHECK(b.xyz.size() == 9);
  const ParsedPoints c = read_points("id,elevation,y,x\n7,10,2,1\n", "c.csv");
  CHECK(c.xyz == std::vector<double>{1, 2, 10});
}

TEST_CASE("text files: errors name file, line and value") {
  CHECK(read_error("0,0,1\n1,0\n") == "f.csv: line 2: expected 3 numbers x y z, got 2 fields '1,0'");
  CHECK(read_error("0,0,1\n1,abc,2\n") == "f.csv: line 2: y is 'abc', not a number");
  CHECK(read_error("0,0,1\n1,1,nan\n") == "f.csv: line 2: z is 'nan', expected a finite number");
  CHECK(read_error("") == "f.csv: the file is empty");
  CHECK(read_error("x,y,z\n") == "f.csv: no points found");
}

TEST_CASE("JSON files") {
  const ParsedPoints a = read_points("[[0, 0, 1], [1, 0, 2],\n [0, 1, 3e0]]", "a.json");
  CHECK(a.xyz == std::vector<double>{0, 0, 1, 1, 0, 2, 0, 1, 3});
  CHECK(a.lines == std::vector<int>{1, 1, 2});
  const ParsedPoints b = read_points("[{\"x\": 1, \"y\": 2, \"z\": 3}]", "b.json");
  CHECK(b.xyz == std::vector<double>{1, 2, 3});
  CHECK(read_error("[[0, 0, 1], [1, 0]]", "a.json") == "a.json: line 1: point 1: expected [x, y, z] with 3 numbers, found ']]'");
  CHECK(read_error("[[0, 0, 1],\n [1, \"a\", 2]]", "a.json") == "a.json: line 2: y is '\"a\", 2]]', not a number");
  CHECK(read_error("[[0, 0, 1]", "a.json") == "a.json: line 1: expected ',' or ']', found end of file");
}

TEST_CASE("ESRI ASCII grids: rows north to south, NODATA skipped") {
  const std::string asc =
      "ncols 3\nnrows 2\nxllcorner 10\nyllcorner 20\ncellsize 2\nNODATA_value -9999\n"
      "1 2 3\n4 -9999 6\n";
  const ParsedPoints g = read_points(asc, "g.asc");
  REQUIRE(g.xyz.size() == 15);
  // First row is the northern one: y = 20 + 1 + 2 (cell centres).
  CHECK(g.xyz[0] == 11);
  CHECK(g.xyz[1] == 23);
  CHECK(g.xyz[2] == 1);
  CHECK(g.xyz[10] == 21);  // second row: y = 21, the NODATA cell is absent
  CHECK(g.xyz[14] == 6);
  CHECK(read_error("ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 5\n", "g.asc") ==
        "g.asc: line 7: expected ncols = 3 values, got 2");
  CHECK(read_error("ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\n1 2 3\n", "g.asc") ==
        "g.asc: line 5: grid header is missing cellsize");
}
