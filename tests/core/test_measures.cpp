#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "hodt/delaunay.hpp"
#include "hodt/measures.hpp"
#include "hodt/objectives.hpp"

using namespace hodt;

namespace {
// A diamond (1,0), (0,1), (-1,0), (0,-1) around the centre (0,0): vertex 4 is the
// only interior vertex, with the four others as neighbours.
Mesh diamond(double z0, double z1, double z2, double z3, double zc) {
  return delaunay({1, 0, z0, 0, 1, z1, -1, 0, z2, 0, -1, z3, 0, 0, zc});
}
uint8_t centre_class(const Mesh& m) { return measure(m).vertex_class[4]; }
uint8_t centre_extremum(const Mesh& m) { return measure(m).extremum[4]; }
}  // namespace

TEST_CASE("vertex classes on hand-checked stars") {
  CHECK(centre_class(diamond(0, 0, 0, 0, 1)) == kConvex);   // a peak
  CHECK(centre_extremum(diamond(0, 0, 0, 0, 1)) == kLocalMaximum);
  CHECK(centre_class(diamond(0, 0, 0, 0, -1)) == kConcave); // a pit
  CHECK(centre_extremum(diamond(0, 0, 0, 0, -1)) == kLocalMinimum);
  CHECK(centre_class(diamond(1, -1, 1, -1, 0)) == kMixed);  // a saddle
  CHECK(centre_extremum(diamond(1, -1, 1, -1, 0)) == kNotExtremum);
  CHECK(centre_class(diamond(1, 2, -1, -2, 0)) == kFlat);   // z = x + 2y
  // On the plane z = 0 with one neighbour strictly below: convex, not a maximum.
  CHECK(centre_class(diamond(0, 0, 0, -1, 0)) == kConvex);
  CHECK(centre_extremum(diamond(0, 0, 0, -1, 0)) == kNotExtremum);
  CHECK(centre_class(diamond(0, 1, 0, 0, 0)) == kConcave);
  // A tilted plane with one neighbour above: concave.
  CHECK(centre_class(diamond(1, 2, -1, -1.5, 0)) == kConcave);
  // Hull vertices are boundary.
  const Measures ms = measure(diamond(0, 0, 0, 0, 1));
  for (int v = 0; v < 4; ++v) CHECK(ms.vertex_class[v] == kBoundary);
  CHECK(ms.degree[4] == 4);
  CHECK(ms.degree[0] == 3);
}

TEST_CASE("edge shapes: ridge, valley, flat") {
  // Triangles (0,0),(1,0),(0,1) and (1,0),(1,1),(0,1) share the edge (1,0)-(0,1).
  auto shape = [](double z_apex) -> uint8_t {
    const Mesh m = delaunay({0, 0, z_apex, 1, 0, 0, 0, 1, 0, 1, 1, z_apex});
    const Measures ms = measure(m);
    for (uint32_t e = 0; e < m.halfedges.size(); ++e)
      if (m.halfedges[e] >= 0) return ms.edge_shape[e];
    return kHullEdge;
  };
  // Which diagonal the (cocircular) square gets is the perturbation's choice; with
  // equal apex heights the shape is the same either way for these heights.
  const Mesh m = delaunay({0, 0, -1, 1, 0, 0, 0, 1, 0, 1, 1, -1});
  const bool diagonal_10_01 = m.halfedges.size() && [&] {
    for (uint32_t e = 0; e < m.halfedges.size(); ++e)
      if (m.halfedges[e] >= 0) return (m.origin(e) == 1 && m.target(e) == 2) || (m.origin(e) == 2 && m.target(e) == 1);
    return false;
  }();
  if (diagonal_10_01) {
    CHECK(shape(-1) == kConvexEdge);  // both apexes below the diagonal's ends: a ridge
    CHECK(shape(1) == kReflexEdge);
    CHECK(shape(0) == kFlatEdge);
  } else {
    CHECK(shape(-1) == kReflexEdge);  // the other diagonal runs through the low corners
    CHECK(shape(1) == kConvexEdge);
    CHECK(shape(0) == kFlatEdge);
  }
}

TEST_CASE("pair measures") {
  const double a[3] = {0, 0, 0}, b[3] = {2, 0, 0}, c[3] = {0, 2, 0}, d[3] = {2, 2, 2};
  CHECK(triangle_area(a, b, c) == 2);
  CHECK(area_ratio(2, 0.5) == 4);
  CHECK(area_ratio(0.5, 2) == 4);
  const double* t1[3] = {a, b, c};
  const double* t2[3] = {b, d, c};
  // Normals: (0,0,1) and the normal of b, d, c: (b-d... ) compute: plane z = x + y - 2 → normal (-1,-1,1).
  CHECK(normal_angle(t1, t2) == doctest::Approx(std::acos(1 / std::sqrt(3.0))));
  CHECK(normal_angle(t1, t1) == 0);
  // Smallest circle of the unit square's corners: radius sqrt(2)/2 * 2 = sqrt(2).
  CHECK(enclosing_circle(a, b, c, d) == doctest::Approx(std::sqrt(2.0)));
  // An obtuse configuration: the diameter circle of the far pair.
  const double p[3] = {0, 0, 0}, q[3] = {10, 0, 0}, r[3] = {5, 1, 0}, s[3] = {5, -1, 0};
  CHECK(enclosing_circle(p, q, r, s) == doctest::Approx(5));
  CHECK(edge_length(a, d) == doctest::Approx(std::sqrt(8.0)));
}

TEST_CASE("all 13 objectives on a hand-checked terrain") {
  const Mesh m = diamond(0, 0, 0, 0, 1);  // a pyramid on the diamond
  const auto v = evaluate_all(m);
  auto at = [&](Objective o) { return v[static_cast<size_t>(o)]; };
  CHECK(at(Objective::MaxConvexVertices) == 1);
  CHECK(at(Objective::MinMixedVertices) == 0);
  CHECK(at(Objective::MinLocalMinima) == 0);
  CHECK(at(Objective::MinLocalExtrema) == 1);
  CHECK(at(Objective::MaxConvexEdges) == 4);  // the four spokes are ridges
  CHECK(at(Objective::MinmaxDegree) == 4);
  CHECK(at(Objective::MinTotalEdgeLength) == doctest::Approx(4 * std::sqrt(2.0) + 4));
  CHECK(at(Objective::MinmaxTriangleArea) == 0.5);
  CHECK(at(Objective::MinmaxEdgeAreaRatio) == 1);
  CHECK(at(Objective::MinmaxVertexAreaRatio) == 1);
  // Adjacent faces of the pyramid: normals (1,1,1) and (-1,1,1) (normalised): angle acos(1/3).
  CHECK(at(Objective::MinmaxEdgeNormalAngle) == doctest::Approx(std::acos(1.0 / 3)));
  // Opposite faces share only the apex: normals (1,1,1) and (-1,-1,1): acos(-1/3).
  CHECK(at(Objective::MinmaxVertexNormalAngle) == doctest::Approx(std::acos(-1.0 / 3)));
  // Two adjacent faces span (1,0), (0,1), (-1,0) and the centre: circle radius 1.
  CHECK(at(Objective::MinmaxEdgeEnclosingCircle) == doctest::Approx(1));
}

TEST_CASE("objective table and ids") {
  CHECK(objectives().size() == 13);
  for (const auto& i : objectives()) {
    CHECK(parse_objective(i.id) == i.objective);
    CHECK(&info(i.objective) == &i);
  }
  CHECK_FALSE(parse_objective("max-fun"));
}

#include <string>

#include "objectives/objective_terms.hpp"
#include "objectives/pair_measures.hpp"

TEST_CASE("the objective table is what the engines read") {
  for (const auto& i : objectives()) {
    const std::string id = i.id;
    INFO(id);
    const ObjectiveTerms& d = objective_terms_inside(i.objective);
    CHECK(d.combine == i.combine);
    // The min-max objectives are named minmax-*; the rest are sums.
    CHECK((i.combine == Combine::Max) == (id.rfind("minmax-", 0) == 0));
    // The paper's NP-hardness results (Theorems 4, 5 and 6).
    CHECK(i.polynomial == (id != "max-convex-edges" && id != "min-mixed-vertices" && id != "minmax-degree"));
    CHECK((std::string(i.reference).rfind("NP-hard", 0) == 0) == !i.polynomial);
    // Pairs: minmax-edge-* over edge-adjacent pairs, minmax-vertex-* over vertex-adjacent ones.
    const bool edge_pairs = id.rfind("minmax-edge-", 0) == 0, vertex_pairs = id.rfind("minmax-vertex-", 0) == 0;
    CHECK(is_pair_objective(i.objective) == (edge_pairs || vertex_pairs));
    CHECK((d.site == TermSite::EdgePair) == edge_pairs);
    CHECK((d.site == TermSite::VertexPair) == vertex_pairs);
    CHECK((d.measure != PairMeasure::None) == (d.pair != nullptr));
    CHECK(std::string(i.unit).size() > 0);
  }
}

#include "generators.hpp"
#include "geometry/portable_math.hpp"

TEST_CASE("portable_atan and portable_angle agree with libm within 1 ulp") {
  hodt::test::Rng r(3);
  for (int i = 0; i < 200000; ++i) {
    const double x = std::ldexp(r.uniform() * 2 - 1, r.below(80) - 40);
    const double a = hodt::portable_atan(x), b = std::atan(x);
    CHECK(std::abs(a - b) <= std::abs(b) * 2.3e-16);
    const double y = std::abs(std::ldexp(r.uniform(), r.below(40) - 20));
    const double c = hodt::portable_angle(y, x), d = std::atan2(y, x);
    CHECK(std::abs(c - d) <= std::abs(d) * 4.5e-16);
  }
  CHECK(hodt::portable_angle(0, 1) == 0);
  CHECK(hodt::portable_angle(1, 0) == doctest::Approx(M_PI / 2));
  CHECK(hodt::portable_angle(0, -1) == doctest::Approx(M_PI));
}

TEST_CASE("enclosing circle: repeated grid shapes come from the cache, bit for bit") {
  // A reprojected raster's cells (exact differences, a few shapes over and over),
  // near-zero coordinates (differences not exact: never cached) and random quads.
  std::vector<std::array<double, 3>> pts;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) pts.push_back({731012.3456789 + 74.98765 * i, 4100000.25 + 74.98765 * j, 0});
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) pts.push_back({-0.3 + 0.1 * i, 1e-17 * j - 0.25 + 0.1 * j, 0});
  uint64_t s = 12345;
  auto next = [&] { return (s = s * 6364136223846793005ull + 1442695040888963407ull) >> 11; };
  size_t compared = 0;
  for (int round = 0; round < 2; ++round)  // (the second round reads the cache)
    for (size_t q = 0; q < 20000; ++q) {
      const size_t base = next() % pts.size();
      const double* p[4];
      for (int k = 0; k < 4; ++k) {  // a quad near base: a cell, a pair of cells, or random points
        const size_t near = (base + (next() % 3) + (next() % 3) * 12) % pts.size();
        p[k] = pts[q % 3 == 0 ? next() % pts.size() : near].data();
      }
      if (p[0] == p[1] || p[0] == p[2] || p[0] == p[3] || p[1] == p[2] || p[1] == p[3] || p[2] == p[3]) continue;
      const double cached = enclosing_circle(p[0], p[1], p[2], p[3]);
      const double fresh = detail::enclosing_circle_uncached(p[3], p[1], p[0], p[2]);
      REQUIRE(std::memcmp(&cached, &fresh, sizeof cached) == 0);
      ++compared;
    }
  CHECK(compared > 20000);
}
