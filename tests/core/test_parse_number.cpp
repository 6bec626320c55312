// Numbers as text files hold them, read to the double strtod gives, bit for bit:
// short decimals, 17 significant digits (numpy's savetxt('%.17g'), pandas, GDAL),
// subnormals, huge magnitudes, halfway cases; and the decimal comma.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "generators.hpp"
#include "io/parse_number.hpp"

using namespace hodt;

namespace {

uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// glibc's strtod rounds correctly: the reference.
void same_as_strtod(const std::string& tok) {
  double got = 0;
  const bool ok = parse_double(tok, got);
  char* end = nullptr;
  const double want = std::strtod(tok.c_str(), &end);
  const bool want_ok = !tok.empty() && end == tok.c_str() + tok.size();
  CAPTURE(tok);
  REQUIRE(ok == want_ok);
  if (ok) REQUIRE(bits(got) == bits(want));
}

std::string random_digits(test::Rng& rng, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += static_cast<char>('0' + rng.below(10));
  return s;
}

}  // namespace

TEST_CASE("numbers: the edge cases read as strtod reads them") {
  for (const char* tok :
       {"0", "-0", "+0", "0.1", "-0.1", "+.5", "5.", ".", "-", "+", "", "1e5", "1E+03", "1e-3", "1e", "1e+", "e5", "inf", "-inf",
        "+inf", "Infinity", "nan", "NaN", "1..2", "1.2.3", "9007199254740992", "9007199254740993", "900719925474099.3",
        "0.0000000000000000000001", "0.00000000000000000000001", "731012.3456789", "5501234.5", "-12.000",
        "0.0669944337466229500000000000000000", "123456789012345678901234567890",
        // subnormals, the smallest, the largest, past them both
        "4.9406564584124654e-324", "2.4703282292062327e-324", "2.4703282292062328e-324", "2.2250738585072011e-308",
        "2.2250738585072014e-308", "1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623159e308", "1e309",
        "1e-400", "-1e-400", "1e-320",
        // halfway between two doubles, and one digit past it far out
        "9007199254740993.0000000000000000000000000000001", "0.1000000000000000055511151231257827021181583404541015625",
        "2.2250738585072012e-308", "8.988465674311580536566680e307", "1.00000000000000011102230246251565404236316680908203125",
        "1.00000000000000011102230246251565404236316680908203124", "1.00000000000000011102230246251565404236316680908203126"})
    same_as_strtod(tok);
}

TEST_CASE("numbers: random short, 17-digit, subnormal and huge decimals read as strtod reads them") {
  test::Rng rng(56);
  char buf[64];
  for (int n = 0; n < 100000; ++n) {
    // a random double (any exponent, subnormals included) printed as numpy's savetxt('%.17g') does
    uint64_t b = rng.next() & ~(uint64_t(0x7FF) << 52);
    b |= static_cast<uint64_t>(rng.below(2047)) << 52;  // (2047: infinities and NaN left out)
    double v;
    std::memcpy(&v, &b, sizeof v);
    std::snprintf(buf, sizeof buf, "%.17g", v);
    same_as_strtod(buf);
    std::snprintf(buf, sizeof buf, "%.*g", 1 + rng.below(17), v);  // fewer digits
    same_as_strtod(buf);
    // coordinates as DEMs hold them: UTM metres with 1 to 25 decimals
    same_as_strtod((rng.below(4) == 0 ? "-" : "") + random_digits(rng, 1 + rng.below(7)) + "." +
                   random_digits(rng, 1 + rng.below(25)));
    // any run of digits with a point anywhere and an exponent, signed
    std::string tok = rng.below(3) == 0 ? (rng.below(2) ? "-" : "+") : "";
    const std::string digits = random_digits(rng, 1 + rng.below(30));
    const int point = rng.below(static_cast<int>(digits.size()) + 2) - 1;  // -1: none
    for (int i = 0; i < static_cast<int>(digits.size()); ++i) {
      if (i == point) tok += '.';
      tok += digits[i];
    }
    if (rng.below(2)) tok += (rng.below(2) ? "e" : "E") + std::string(rng.below(3) == 0 ? "-" : "") + std::to_string(rng.below(330));
    same_as_strtod(tok);
  }
  // the subnormal range densely: 17 digits below 2.2250738585072014e-308
  for (int n = 0; n < 20000; ++n) {
    std::snprintf(buf, sizeof buf, "%.17ge-%d", 1 + 9 * rng.uniform(), 309 + rng.below(16));
    same_as_strtod(buf);
  }
}

TEST_CASE("numbers: not decimals, though strtod takes them") {
  double v = 0;
  // (the readers' tokens never hold spaces; hex floats are no coordinate format)
  for (const char* tok : {"0x10", "0X1p3", " 1", "1 ", "\t1", "+-1", "++1", "-+1", "1,5"}) {
    CAPTURE(tok);
    CHECK_FALSE(parse_double(tok, v));
  }
}

TEST_CASE("numbers: a decimal comma reads as the point does") {
  test::Rng rng(5);
  char buf[64];
  for (int n = 0; n < 20000; ++n) {
    uint64_t b = rng.next() & ~(uint64_t(0x7FF) << 52);
    b |= static_cast<uint64_t>(rng.below(2047)) << 52;
    double v;
    std::memcpy(&v, &b, sizeof v);
    std::snprintf(buf, sizeof buf, "%.17g", v);
    std::string point = buf, comma = buf;
    for (char& c : comma)
      if (c == '.') c = ',';
    double a = 0, c = 0;
    CAPTURE(comma);
    REQUIRE(parse_double(point, a));
    REQUIRE(parse_double(comma, c, ','));
    REQUIRE(bits(a) == bits(c));
  }
  double v = 0;
  CHECK(parse_double("+1,5", v, ','));
  CHECK(v == 1.5);
  CHECK_FALSE(parse_double("1.5", v, ','));
  CHECK_FALSE(parse_double("1,2,3", v, ','));
}
