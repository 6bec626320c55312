// Optimising over k-OD triangulations: the enumerator's counts, exact results
// against an independent enumeration, and every result k-OD.
#include <doctest/doctest.h>

#include <fstream>
#include <functional>
#include <map>
#include <set>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "hodt/predicates.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/phases/phase_table.hpp"
#include "higher_order/search/flip_search.hpp"
#include "mesh/circle_count.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// All triangulations by brute force: exact cover of the hull by every empty
// triangle of the points (no usefulness pruning), then keep the k-OD ones.
void all_triangulations(const Mesh& dt, const std::function<void(const std::vector<Tri>&)>& visit) {
  const uint32_t n = dt.num_vertices();
  std::vector<Tri> empty;
  for (uint32_t a = 0; a < n; ++a)
    for (uint32_t b = 0; b < n; ++b)
      for (uint32_t c = 0; c < n; ++c) {
        if (!(a < b && a < c) || b == c || orient2d(dt.point(a), dt.point(b), dt.point(c)) <= 0) continue;
        bool ok = true;
        for (uint32_t p = 0; p < n && ok; ++p)
          if (p != a && p != b && p != c)
            ok = !(orient2d(dt.point(a), dt.point(b), dt.point(p)) >= 0 && orient2d(dt.point(b), dt.point(c), dt.point(p)) >= 0 &&
                   orient2d(dt.point(c), dt.point(a), dt.point(p)) >= 0);
        if (ok) empty.push_back({a, b, c});
      }
  // Choose triangles covering the total area exactly with no two overlapping:
  // recursive over the lowest uncovered hull/front edge, as a plain list search.
  double hull2 = 0;
  for (size_t i = 0; i < dt.hull.size(); ++i) {
    const double* p = dt.point(dt.hull[i]);
    const double* q = dt.point(dt.hull[(i + 1) % dt.hull.size()]);
    hull2 += p[0] * q[1] - p[1] * q[0];
  }
  const size_t want = 2 * n - dt.hull.size() - 2;
  std::vector<Tri> chosen;
  auto overlap = [&](const Tri& s, const Tri& t) {  // interiors intersect
    // Separating axis over the six edges (exact orientations): disjoint interiors
    // iff some edge of one has the other entirely on or outside its right side.
    auto separated = [&](const Tri& x, const Tri& y) {
      for (int i = 0; i < 3; ++i) {
        bool all_out = true;
        for (uint32_t v : y) all_out = all_out && orient2d(dt.point(x[i]), dt.point(x[(i + 1) % 3]), dt.point(v)) <= 0;
        if (all_out) return true;
      }
      return false;
    };
    return !separated(s, t) && !separated(t, s);
  };
  std::function<void(size_t)> rec = [&](size_t from) {
    if (chosen.size() == want) {
      visit(chosen);
      return;
    }
    for (size_t i = from; i < empty.size(); ++i) {
      bool ok = true;
      for (const Tri& c : chosen) ok = ok && !overlap(c, empty[i]);
      if (!ok) continue;
      chosen.push_back(empty[i]);
      rec(i + 1);
      chosen.pop_back();
    }
  };
  rec(0);
}

uint32_t inside_count(const Mesh& m, const Tri& t) {
  uint32_t c = 0;
  for (uint32_t v = 0; v < m.num_vertices(); ++v)
    c += v != t[0] && v != t[1] && v != t[2] && in_circle(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(v));
  return c;
}

}  // namespace

TEST_CASE("the k-OD enumerator: 2^m first order triangulations, Catalan numbers in convex position") {
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(uniform_points(12, seed)).xyz));
    if (fo.num_quads() > 12) continue;
    uint64_t count = 0;
    CHECK(enumerate_k_order(fo.base, 1, 10'000'000, [&](const std::vector<Tri>&) { ++count; }));
    CHECK(count == (uint64_t(1) << fo.num_quads()));
  }
  // n points in convex position, k >= n: every triangulation, Catalan(n - 2) of them.
  const uint64_t catalan[] = {1, 1, 2, 5, 14, 42, 132, 429, 1430};
  for (int n = 3; n <= 10; ++n) {
    std::vector<double> p;
    for (int i = 0; i < n; ++i) p.insert(p.end(), {double(i), double(i * i), 0.0});
    const Mesh dt = delaunay(p);
    uint64_t count = 0;
    CHECK(enumerate_k_order(dt, static_cast<uint32_t>(n), 10'000'000, [&](const std::vector<Tri>&) { ++count; }));
    CHECK(count == catalan[n - 2]);
  }
}

TEST_CASE("exact k-OD optimisation equals an independent exhaustive enumeration") {
  int done = 0;
  for (uint64_t seed = 1; done < 40; ++seed) {
    Rng r(seed);
    const int n = 6 + r.below(3);
    const std::vector<double> p = seed % 2 ? uniform_points(n, seed) : dem_points(n, seed);
    const FirstOrder fo = first_order(delaunay(validate_points(p).xyz));
    ++done;
    for (uint32_t k : {2u, 3u}) {
      // Independent: all triangulations, keep the k-OD ones, best value.
      std::map<Objective, double> best;
      uint64_t count = 0;
      all_triangulations(fo.base, [&](const std::vector<Tri>& tris) {
        for (const Tri& t : tris)
          if (inside_count(fo.base, t) > k) return;
        ++count;
        const Mesh m = mesh_of(fo.base.coords, tris);
        for (const auto& oi : objectives()) {
          const double v = evaluate(oi.objective, m);
          if (!best.count(oi.objective) || better(oi.sense, v, best[oi.objective])) best[oi.objective] = v;
        }
      });
      uint64_t mine = 0;
      enumerate_k_order(fo.base, k, 10'000'000, [&](const std::vector<Tri>&) { ++mine; });
      CHECK(mine == count);
      for (Objective o : {Objective::MinLocalMinima, Objective::MaxConvexEdges, Objective::MinmaxDegree, Objective::MinTotalEdgeLength}) {
        const KOrderResult res = solve_k_order(fo, o, k, {});
        CHECK(res.optimal);
        CHECK(res.value == best[o]);
        CHECK(is_k_order(res.triangulation, fo.base, k));
      }
    }
  }
}

TEST_CASE("large instances: every objective answers, k-OD, never worse than first order") {
  const FirstOrder fo = first_order(delaunay(validate_points(dem_points(1500, 9)).xyz));
  for (uint32_t k : {2u, 4u}) {
    for (const auto& oi : objectives()) {
      CAPTURE(oi.id);
      CAPTURE(k);
      const KOrderResult r = solve_k_order(fo, oi.objective, k, {});
      CHECK(is_k_order(r.triangulation, fo.base, k));
      CHECK(validate(r.triangulation) == "");
      CHECK(r.value == evaluate(oi.objective, r.triangulation));
      CHECK(r.optimal != r.bound.has_value());
      if (r.bound) CHECK(better(oi.sense, *r.bound, r.value));  // a gap is left
      SolveOptions first;
      first.method = Method::Auto;
      const Solution s1 = solve(fo, oi.objective, first);
      if (s1.optimal && r.optimal) CHECK(!better(oi.sense, s1.value, r.value));
    }
  }
}

TEST_CASE("k-OD flips: valid, never worse, and a local optimum (no single k-OD flip improves)") {
  // One pass of the definition over every edge: a strictly convex quad whose
  // two new triangles are k-OD and whose flip strictly improves the objective
  // (counts: the change of the whole equals that of the terms around the quad).
  auto improving_flips = [](Mesh m, const Mesh& dt, uint32_t k, Objective o) {
    CircleCounter circles(dt);
    uint32_t found = 0;
    const double value = evaluate(o, m);
    for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
      const int32_t f = m.halfedges[e];
      if (f < static_cast<int32_t>(e)) continue;
      const uint32_t a = m.origin(e), b = m.target(e), c = m.apex(e), x = m.apex(static_cast<uint32_t>(f));
      const int sa = orient2d(m.point(c), m.point(x), m.point(a)), sb = orient2d(m.point(c), m.point(x), m.point(b));
      if (sa == 0 || sb == 0 || sa == sb) continue;
      if (circles.count(a, x, c, k) > k || circles.count(x, b, c, k) > k) continue;
      flip_edge(m, e);
      found += better(info(o).sense, evaluate(o, m), value);
      flip_edge(m, e);
    }
    return found;
  };
  int runs = 0, flipped = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed)
    for (uint32_t k : {1u, 2u, 3u}) {
      const std::vector<double> p = seed % 3 == 0 ? grid_points(10, 12, seed, true) : seed % 3 == 1 ? dem_points(150, seed) : uniform_points(150, seed);
      const Mesh dt = delaunay(validate_points(p).xyz);
      for (Objective o : {Objective::MaxConvexVertices, Objective::MaxConvexEdges, Objective::MinMixedVertices,
                          Objective::MinLocalMinima, Objective::MinLocalExtrema}) {
        CAPTURE(seed);
        CAPTURE(k);
        const std::string id = info(o).id;
        CAPTURE(id);
        Mesh got = dt;
        const uint32_t flips = improve_by_flips(got, dt, k, o);
        CHECK(validate(got) == "");
        CHECK(is_k_order(got, dt, k));
        CHECK_FALSE(better(info(o).sense, evaluate(o, dt), evaluate(o, got)));
        CHECK(improving_flips(got, dt, k, o) == 0);
        ++runs;
        flipped += flips > 0;
      }
    }
  MESSAGE(runs << " local searches, " << flipped << " with flips");
  CHECK(flipped > runs / 3);
}

// docs/higher-order.md describes the solve's phases in a table: it must list the
// code's rows, in the code's order, and no others.
TEST_CASE("the phase table of docs/higher-order.md is the driver's") {
  std::ifstream in(std::string(HODT_FIXTURES) + "/../../docs/higher-order.md");
  REQUIRE(in);
  std::vector<std::string> documented;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("### The phases", 0) == 0) inside = true;
    else if (inside && line.rfind("#", 0) == 0) break;
    else if (inside && line.rfind("| ", 0) == 0 && line.rfind("| phase ", 0) != 0)
      documented.push_back(line.substr(2, line.find(" |", 2) - 2));
  }
  std::vector<std::string> code;
  for (const KOrderPhase& phase : k_order_phases()) code.push_back(phase.name);
  CHECK(documented == code);
}
