// The coordinate range (points.hpp): coordinates whose magnitude would make a
// measure overflow, underflow or lose its exactness are rejected with a message
// naming the point, the coordinate and the range, everywhere points come in; and
// at the ends of the range every measure stays finite and accurate.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "hodt/brute_force.hpp"
#include "hodt/error.hpp"
#include "hodt/measures.hpp"
#include "hodt/points.hpp"
#include "hodt/read_points.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"
#include "exact_reference.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string range_error(const std::string& point, const char* axis, const std::string& value) {
  return point + ": " + axis + " is " + value + ", outside the supported range: every coordinate must be 0 or of magnitude from 1e-45 to 1e+45";
}

const std::vector<double> kSquare = {0, 0, 0, 1, 0, 1, 1, 1, 0, 0, 1, 1, 0.5, 0.4, 2};

}  // namespace

TEST_CASE("coordinate range: tiny, subnormal and huge coordinates are rejected with the range") {
  auto with = [](size_t i, double v) {
    std::vector<double> p = kSquare;
    p[i] = v;
    return error_of([&] { validate_points(p); });
  };
  CHECK(with(3, 1e-300) == range_error("point 1", "x", "1e-300"));
  CHECK(with(7, 5e-324) == range_error("point 2", "y", "5e-324"));
  CHECK(with(14, -1e300) == range_error("point 4", "z", "-1e+300"));
  CHECK(with(4, 1e46) == range_error("point 1", "y", "1e+46"));
  CHECK(with(4, 1e-46) == range_error("point 1", "y", "1e-46"));
  // The ends of the range and zero are in it (also signed zero).
  for (double v : {1e-45, -1e-45, 1e45, -1e45, 0.0, -0.0}) CHECK(with(14, v) == "");
  CHECK(with(3, 1e45) == "");
  // A file names the line.
  CHECK(error_of([] { Terrain::from_points(read_points("0 0 0\n1 0 0\n0 1e-320 0\n", "f.csv").xyz, Dedupe::Error,
                                             PointLabels{{1, 2, 3}}); })
            .find("point 2 (line 3): y is ") == 0);
}

TEST_CASE("coordinate range: live edits and given triangulations check it too") {
  Terrain t = Terrain::from_points(kSquare);
  CHECK(error_of([&] { t.add_point(1e-300, 0.5, 0); }) == range_error("point 5", "x", "1e-300"));
  CHECK(error_of([&] { t.move_point(2, 0.5, 2e45, 0); }) == range_error("point 2", "y", "2e+45"));
  CHECK(error_of([&] { t.move_point(4, 0.5, 0.4, 1e-310); }) == range_error("point 4", "z", "1e-310"));
  CHECK(t.num_input_points() == 5);
  CHECK(t.structure().base.num_vertices() == 5);
  std::vector<double> p = kSquare;
  p[0] = -1e50;
  CHECK(error_of([&] { Terrain::from_triangulation(p, {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}, {}); }) ==
        range_error("point 0", "x", "-1e+50"));
}

TEST_CASE("coordinate range: at its ends every measure is finite and accurate") {
  // The largest triangles of the range next to the smallest: a few ulps apart at
  // 1e-45 (the finest spacing), a span of 2e45.
  const double t = 1e-45, u = std::nextafter(t, 1.0);
  const std::vector<double> xyz = {-1e45, -1e45, 1e45, 1e45, -1e45, -1e45, 0, 1e45, 1e-45,
                                   t, t, 0, u, t, 1e45, t, u, -1e-45, -t, -t, 1e45};
  const Terrain terrain = Terrain::from_points(xyz);
  const Mesh& m = terrain.structure().base;
  ExactObjectives exact_values([&](uint32_t v) { return m.point(v); }, m.num_vertices());
  for (const auto& oi : objectives()) {
    CAPTURE(oi.id);
    const double v = evaluate(oi.objective, m);
    CHECK(std::isfinite(v));
    if (ExactObjectives::supports(oi.objective)) {
      CHECK(ulps_off(v, exact_values.value(oi.objective, triangles_of(m))) <= 64);
    }
    SolveOptions options;
    options.method = Method::Auto;
    const Solution s = solve(terrain.structure(), oi.objective, options);
    CHECK(std::isfinite(s.value));
    // The solvers' filters and models agree with every triangulation measured directly.
    if (s.optimal) CHECK(s.value == brute_force(terrain.structure(), oi.objective).value);
  }
  CHECK(evaluate(Objective::MinmaxVertexAreaRatio, m) > 1e180);
  // Normal angles of triangles far from flat at both ends of the range.
  CHECK(evaluate(Objective::MinmaxVertexNormalAngle, m) > 1);
  for (uint32_t k = 0; k < m.num_triangles(); ++k) {
    const double* c[3] = {m.point(m.triangles[3 * k]), m.point(m.triangles[3 * k + 1]), m.point(m.triangles[3 * k + 2])};
    CHECK(std::isfinite(circumradius(c[0], c[1], c[2])));
    CHECK(triangle_area(c[0], c[1], c[2]) > 0);
  }
}
