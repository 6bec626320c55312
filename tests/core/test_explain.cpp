// explain(): what the solvers recorded is what they decided. Each recorded
// structure is checked against an independent reading of the instance: the
// 2-SAT assignment satisfies its clauses and measures at most its threshold, a
// conflict's literals imply each other, Baker's shift values are the measured
// values of their choices, the region counts multiply to the enumeration's.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "hodt/brute_force.hpp"
#include "hodt/delaunay.hpp"
#include "hodt/explain.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "objectives/pair_measures.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

FirstOrder terrain_of(const std::vector<double>& p) { return first_order(delaunay(validate_points(p).xyz)); }

// Literals reachable from `from` in the implication graph of the clauses.
std::set<uint32_t> implied(const std::vector<uint32_t>& clauses, uint32_t from) {
  std::set<uint32_t> seen{from};
  std::vector<uint32_t> stack{from};
  while (!stack.empty()) {
    const uint32_t l = stack.back();
    stack.pop_back();
    for (size_t c = 0; c < clauses.size(); c += 2)
      for (int side = 0; side < 2; ++side)
        if ((clauses[c + side] ^ 1) == l && seen.insert(clauses[c + 1 - side]).second) stack.push_back(clauses[c + 1 - side]);
  }
  return seen;
}

}  // namespace

TEST_CASE("explain: each threshold test of the bottleneck search, in full") {
  const Objective pair_objectives[] = {Objective::MinmaxEdgeAreaRatio, Objective::MinmaxEdgeNormalAngle,
                                       Objective::MinmaxEdgeEnclosingCircle, Objective::MinmaxVertexAreaRatio,
                                       Objective::MinmaxVertexNormalAngle};
  uint64_t tests = 0, conflicts = 0;
  // (The search tests the lower bound first, and here it is often the optimum:
  // enough instances for hundreds of tests.)
  for (uint64_t seed = 1; seed <= 240; ++seed) {
    const FirstOrder fo = terrain_of(seed % 2 ? jittered_grid(7, 6, 0.3, seed) : dem_points(40, seed));
    for (Objective o : pair_objectives) {
      SolveOptions options;
      options.trace = true;
      const Explanation e = explain(fo, o, options);
      REQUIRE(e.search);
      const SearchExplanation& s = *e.search;
      REQUIRE(!s.candidates.empty());
      CHECK(std::is_sorted(s.candidates.begin(), s.candidates.end()));
      CHECK(s.candidates.back() == evaluate(o, triangulate(fo, Choice(fo.num_quads(), 0))));
      REQUIRE(s.tests.size() == e.solution.trace.size());
      const uint32_t m = fo.num_quads();
      for (size_t i = 0; i < s.tests.size(); ++i) {
        const ThresholdTest& t = s.tests[i];
        ++tests;
        CHECK(t.threshold == e.solution.trace[i].threshold);
        CHECK(t.satisfiable == e.solution.trace[i].satisfiable);
        CHECK(std::binary_search(s.candidates.begin(), s.candidates.end(), t.threshold));
        if (t.immediate_no) {
          CHECK(!t.satisfiable);
          CHECK((s.floor > t.threshold || t.blocked.size() == 1));
          continue;
        }
        CHECK(t.clauses.size() == 2 * e.solution.trace[i].clauses);
        CHECK(t.forced.size() == 2 * e.solution.trace[i].forced);
        REQUIRE(t.component.size() == 2 * m);
        if (t.satisfiable) {
          REQUIRE(t.assignment.size() == m);
          CHECK(t.conflicts.empty());
          for (size_t c = 0; c < t.clauses.size(); c += 2) {
            const uint32_t a = t.clauses[c], b = t.clauses[c + 1];
            CHECK((t.assignment[a >> 1] == (a & 1) || t.assignment[b >> 1] == (b & 1)));
          }
          for (size_t f = 0; f < t.forced.size(); f += 2) CHECK(t.assignment[t.forced[f]] == t.forced[f + 1]);
          // Independent: the assignment's triangulation measures at most t.
          CHECK(evaluate(o, triangulate(fo, t.assignment)) <= t.threshold);
        } else {
          REQUIRE(!t.conflicts.empty());
          for (uint32_t q : t.conflicts) {
            ++conflicts;
            CHECK(implied(t.clauses, 2 * q).count(2 * q + 1));
            CHECK(implied(t.clauses, 2 * q + 1).count(2 * q));
          }
        }
      }
      // The optimum is the smallest threshold answered yes (or the lowest candidate).
      double best = s.candidates.back();
      for (const ThresholdTest& t : s.tests)
        if (t.satisfiable) best = std::min(best, t.threshold);
      CHECK(e.solution.value == best);
    }
  }
  CHECK(tests > 500);
  CHECK(conflicts > 0);  // the instances exercise "no" through the components
}

TEST_CASE("explain: Baker's shifts are what their choices measure, and bound the optimum") {
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    const FirstOrder fo = terrain_of(jittered_grid(5, 4, 0.3, seed));
    if (fo.num_quads() > 12) continue;
    for (Objective o : {Objective::MaxConvexEdges, Objective::MinMixedVertices}) {
      SolveOptions options;
      options.method = Method::Approx;
      options.epsilon = 0.34;
      const Explanation e = explain(fo, o, options);
      REQUIRE(e.baker);
      const BakerExplanation& b = *e.baker;
      const double opt = brute_force(fo, o).value;
      CHECK(b.layer.size() == fo.num_quads());
      REQUIRE(b.shifts.size() == b.lambda);
      const bool max = o == Objective::MaxConvexEdges;
      double best_bound = max ? INFINITY : -INFINITY, best_value = max ? -INFINITY : INFINITY;
      for (const BakerShiftExplanation& s : b.shifts) {
        CHECK(s.value == evaluate(o, triangulate(fo, s.choice)));
        CHECK((max ? s.bound >= opt : s.bound <= opt));
        CHECK((max ? s.value <= opt : s.value >= opt));
        best_bound = max ? std::min(best_bound, s.bound) : std::max(best_bound, s.bound);
        best_value = max ? std::max(best_value, s.value) : std::min(best_value, s.value);
      }
      CHECK(*e.solution.bound == best_bound);
      CHECK((max ? e.solution.value >= best_value : e.solution.value <= best_value));  // local search only improves
    }
  }
}

TEST_CASE("explain: the exact engine's decomposition covers every quad") {
  const FirstOrder fo = terrain_of(jittered_grid(8, 7, 0.3, 5));
  SolveOptions options;
  options.method = Method::Exact;
  const Explanation e = explain(fo, Objective::MaxConvexEdges, options);
  REQUIRE(e.exact);
  CHECK(e.exact->component.size() == fo.num_quads());
  CHECK(e.exact->width <= options.max_width);
  std::vector<uint32_t> order = e.exact->order;
  std::sort(order.begin(), order.end());
  CHECK(std::adjacent_find(order.begin(), order.end()) == order.end());
  CHECK(e.solution.optimal);
}

TEST_CASE("explain: regions of order k multiply to the number of k-OD triangulations") {
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    const std::vector<double> p = seed % 3 == 0 ? grid_points(4, 3, seed, true) : dem_points(9 + static_cast<int>(seed % 5), seed);
    const FirstOrder fo = terrain_of(p);
    for (uint32_t k = 1; k <= 3; ++k) {
      SolveOptions options;
      options.order = k;
      const Explanation e = explain(fo, Objective::MinLocalMinima, options);
      REQUIRE(e.regions);
      const RegionExplanation& r = *e.regions;
      CHECK(r.order == k);
      CHECK(r.region_of_triangle.size() * 3 == r.triangles.size());
      uint64_t product = 1;
      for (size_t i = 0; i < r.triangulations.size(); ++i) {
        REQUIRE(r.complete[i]);
        product *= r.triangulations[i];
      }
      uint64_t count = 0;
      REQUIRE(enumerate_k_order(fo.base, k, 10'000'000, [&](const std::vector<Tri>&) { ++count; }));
      CHECK(product == count);
      if (k == 1) CHECK(std::count(r.triangulations.begin(), r.triangulations.end(), 2u) == fo.num_quads());
      // Fixed edges are useful; every useful edge of a fixed pair is one of them.
      std::set<std::pair<uint32_t, uint32_t>> useful;
      for (size_t i = 0; i < r.useful.size(); i += 2) useful.insert(std::minmax(r.useful[i], r.useful[i + 1]));
      for (size_t i = 0; i < r.fixed.size(); i += 2) CHECK(useful.count(std::minmax(r.fixed[i], r.fixed[i + 1])));
    }
  }
}

// At a high order the regions merge into ones too large to enumerate (over
// RegionLimits::max_region_triangles): their count is unfinished, and such a
// region still has a choice, so it is never reported as one triangulation.
TEST_CASE("explain: a region whose count was not finished has at least two triangulations") {
  uint64_t unfinished = 0, singles = 0;
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const FirstOrder fo = terrain_of(jittered_grid(8, 8, 0.3, seed));
    for (uint32_t k : {6u, 8u}) {
      SolveOptions options;
      options.order = k;
      const Explanation e = explain(fo, Objective::MinLocalMinima, options);
      REQUIRE(e.regions);
      const RegionExplanation& r = *e.regions;
      std::vector<uint32_t> size(r.triangulations.size(), 0);
      for (int32_t g : r.region_of_triangle) ++size[static_cast<uint32_t>(g)];
      for (size_t g = 0; g < size.size(); ++g) {
        if (size[g] == 1) {
          ++singles;
          CHECK(r.complete[g]);
          CHECK(r.triangulations[g] == 1);
        } else {
          CHECK(r.triangulations[g] >= 2);
        }
        if (!r.complete[g]) ++unfinished;
      }
    }
  }
  CHECK(unfinished > 0);  // the case this test is about occurs
  CHECK(singles > 0);
}

// On rasters the threshold tests are parity systems (pairs tie in large groups),
// decided by union-find: the explanation also runs the 2-SAT and throws should
// they disagree; the optimum is brute force's.
TEST_CASE("explain: on rasters the parity tests agree with 2-SAT and the optimum with brute force") {
  const Objective pair_objectives[] = {Objective::MinmaxEdgeAreaRatio, Objective::MinmaxEdgeNormalAngle,
                                       Objective::MinmaxEdgeEnclosingCircle, Objective::MinmaxVertexAreaRatio,
                                       Objective::MinmaxVertexNormalAngle};
  size_t tests = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    std::vector<double> xyz = grid_points(4 + static_cast<int>(seed % 3), 4 + static_cast<int>(seed % 2), seed, seed % 2 == 0);
    if (seed % 3 != 1)
      for (size_t i = 0; i < xyz.size(); i += 3) xyz[i] = 731012.3456789 + 74.98765 * xyz[i], xyz[i + 1] = 4100000.25 + 74.98765 * xyz[i + 1];
    const FirstOrder fo = terrain_of(xyz);
    for (Objective o : pair_objectives) {
      const Explanation e = explain(fo, o, SolveOptions{});
      REQUIRE(e.search);
      tests += e.search->tests.size();
      CHECK(e.solution.value == brute_force(fo, o).value);
      CHECK(e.solution.choice == solve(fo, o, SolveOptions{}).choice);
    }
  }
  CHECK(tests > 20);  // (most rasters need one test: the lower bound)
}
