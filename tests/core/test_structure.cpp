#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/first_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/points.hpp"
#include "hodt/predicates.hpp"
#include "generators.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// Points strictly inside the circle of (a, b, c), by scanning all points: an
// independent count to check the walking counter and the flippable rule.
int count_inside(const Mesh& m, uint32_t a, uint32_t b, uint32_t c) {
  int k = 0;
  for (uint32_t v = 0; v < m.num_vertices(); ++v)
    if (v != a && v != b && v != c && in_circle(m.point(a), m.point(b), m.point(c), m.point(v))) ++k;
  return k;
}

double area_sum(const Mesh& m) {
  double s = 0;
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    s += triangle_area(m.point(m.triangles[3 * t]), m.point(m.triangles[3 * t + 1]), m.point(m.triangles[3 * t + 2]));
  return s;
}

double hull_area(const Mesh& m) {
  double s = 0;
  for (size_t k = 0; k < m.hull.size(); ++k) {
    const double* p = m.point(m.hull[k]);
    const double* q = m.point(m.hull[(k + 1) % m.hull.size()]);
    s += p[0] * q[1] - p[1] * q[0];
  }
  return s / 2;
}

void check_structure(const std::vector<double>& xyz) {
  const TerrainPoints tp = validate_points(xyz, Dedupe::KeepFirst);
  const Mesh dt = delaunay(tp.xyz);
  REQUIRE(validate(dt) == "");
  const uint32_t n = dt.num_vertices();
  // Euler: 2n - h - 2 triangles; areas sum to the hull's area.
  CHECK(dt.num_triangles() == 2 * n - dt.hull.size() - 2);
  CHECK(std::abs(area_sum(dt) - hull_area(dt)) <= 1e-9 * std::max(1.0, hull_area(dt)));
  // Empty circles (under the perturbation).
  for (uint32_t t = 0; t < dt.num_triangles(); ++t)
    CHECK(count_inside(dt, dt.triangles[3 * t], dt.triangles[3 * t + 1], dt.triangles[3 * t + 2]) == 0);

  const FirstOrder fo = first_order(dt);
  // The flippable rule, checked edge by edge with the scanning count.
  std::set<uint32_t> flippable;
  for (const Quad& q : fo.quads) flippable.insert(q.edge);
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e) {
    const int32_t f = dt.halfedges[e];
    if (f < static_cast<int32_t>(e)) continue;
    const uint32_t a = dt.origin(e), b = dt.target(e), c = dt.apex(e), d = dt.apex(static_cast<uint32_t>(f));
    const int sa = orient2d(dt.point(c), dt.point(d), dt.point(a)), sb = orient2d(dt.point(c), dt.point(d), dt.point(b));
    const bool convex = sa * sb < 0;
    const bool expect = convex && count_inside(dt, a, d, c) <= 1 && count_inside(dt, d, b, c) <= 1;
    CHECK(expect == (flippable.count(e) == 1));
  }
  // No triangle in two quads (assemble would have thrown), every choice valid.
  std::vector<int> seen(dt.num_triangles(), 0);
  for (const Quad& q : fo.quads) {
    ++seen[q.edge / 3];
    ++seen[dt.halfedges[q.edge] / 3];
  }
  for (int s : seen) CHECK(s <= 1);
  Rng r(xyz.size());
  for (int trial = 0; trial < 4; ++trial) {
    Choice c(fo.num_quads());
    for (auto& x : c) x = static_cast<uint8_t>(trial == 0 ? 1 : r.below(2));
    const Mesh m = triangulate(fo, c);
    CHECK(validate(m) == "");
    CHECK(m.hull == dt.hull);
    CHECK(std::abs(area_sum(m) - hull_area(m)) <= 1e-9 * std::max(1.0, hull_area(m)));
    // Every triangle of a first order triangulation is 1-OD.
    for (uint32_t t = 0; t < m.num_triangles(); ++t)
      CHECK(count_inside(m, m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]) <= 1);
  }
}

}  // namespace

TEST_CASE("structure invariants on random points") {
  for (uint64_t seed = 1; seed <= 30; ++seed) check_structure(uniform_points(10 + int(seed) * 3, seed));
}

TEST_CASE("structure invariants on DEM-like points and jittered grids") {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    check_structure(dem_points(60, seed));
    check_structure(jittered_grid(6, 7, 0.3, seed));
  }
}

TEST_CASE("structure invariants on degenerate input: grids and cocircular points") {
  check_structure(grid_points(7, 5, 1));
  check_structure(grid_points(2, 2, 2));
  check_structure(cocircular_points(12, 3));
  check_structure(cocircular_points(4, 4));
  // On a unit grid every cell is a flippable quad.
  const FirstOrder fo = first_order(delaunay(grid_points(5, 4, 1)));
  CHECK(fo.num_quads() == 4 * 3);
}

TEST_CASE("the triangulation is canonical: input order does not matter") {
  std::vector<double> p = uniform_points(40, 9);
  const Mesh a = delaunay(p);
  // Reverse the points: the same triangles up to relabelling.
  std::vector<double> q;
  for (int i = 39; i >= 0; --i) q.insert(q.end(), &p[3 * i], &p[3 * i + 3]);
  const Mesh b = delaunay(q);
  std::set<std::array<uint32_t, 3>> ta, tb;
  auto canon = [](uint32_t x, uint32_t y, uint32_t z) {
    std::array<uint32_t, 3> t = {x, y, z};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  for (uint32_t t = 0; t < a.num_triangles(); ++t) ta.insert(canon(a.triangles[3 * t], a.triangles[3 * t + 1], a.triangles[3 * t + 2]));
  for (uint32_t t = 0; t < b.num_triangles(); ++t) tb.insert(canon(39 - b.triangles[3 * t], 39 - b.triangles[3 * t + 1], 39 - b.triangles[3 * t + 2]));
  CHECK(ta == tb);
}

TEST_CASE("flip_edge twice restores the triangle set") {
  const FirstOrder fo = first_order(delaunay(uniform_points(50, 5)));
  REQUIRE(fo.num_quads() > 0);
  Mesh m = fo.base;
  flip_edge(m, fo.quads[0].edge);
  CHECK(validate(m) == "");
  flip_edge(m, fo.quads[0].edge);
  CHECK(validate(m) == "");
  std::multiset<std::set<uint32_t>> x, y;
  for (uint32_t t = 0; t < m.num_triangles(); ++t) {
    x.insert({m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]});
    y.insert({fo.base.triangles[3 * t], fo.base.triangles[3 * t + 1], fo.base.triangles[3 * t + 2]});
  }
  CHECK(x == y);
}

TEST_CASE("singly-flippable triangulations: accepted and rejected with clear errors") {
  // A unit square split into 4 triangles around a centre point.
  const std::vector<double> p = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 1};
  const std::vector<uint32_t> fan = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  const FirstOrder fo = singly_flippable(p, fan, {});
  CHECK(fo.num_quads() == 0);
  CHECK(fo.base.num_triangles() == 4);
  auto error = [](std::vector<uint32_t> t, std::vector<uint32_t> f,
                  const std::vector<double>& pts = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 1}) -> std::string {
    try {
      singly_flippable(pts, t, f);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  // Edge 0-4 has triangles 0 1 4 and 3 0 4: the quad 1, 4, 3, 0... is not strictly convex.
  CHECK(error(fan, {0, 4}) == "flippable edge 0 (0, 4): its quadrilateral is not strictly convex");
  CHECK(error(fan, {0, 2}) == "flippable edge 0 (0, 2) is not an edge of the triangulation");
  CHECK(error(fan, {0, 1}) == "flippable edge 0 (0, 1) is on the convex hull, not flippable");
  CHECK(error({0, 1, 4, 1, 2, 4, 2, 3, 4}, {}) == "triangles: the boundary is not the convex hull of the points");
  CHECK(error({0, 1, 9}, {}) == "triangle 0: vertex 9 is out of range (5 points)");
  CHECK(error({0, 1, 2, 0, 2, 3}, {}) == "point 4 is not a vertex of any triangle");
  // Clockwise triangles are accepted (reoriented).
  CHECK(error({0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0}, {}) == "");
  // Two flippable edges on one triangle.
  const std::vector<double> q = {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0, 2, 1, 1, 3, 2, 1};
  const std::vector<uint32_t> tq = {0, 1, 4, 1, 5, 4, 1, 2, 5, 2, 3, 5, 3, 4, 5, 3, 0, 4};
  CHECK(error(tq, {}, q) == "");
  CHECK(error(tq, {4, 5, 3, 4}, q).find("touches two flippable edges") != std::string::npos);
}
