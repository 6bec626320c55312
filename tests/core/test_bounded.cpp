// Every solve is bounded: it answers (with a certified value and bound) or refuses
// with a reason, within its memory budget, and it reports progress often enough to
// be cancelled at any time. Wheels are the adversary: about a third of their quads
// meet at the centre, whose vertex term grows as 2^quads.
#include <doctest/doctest.h>

#include <ctime>
#include <optional>
#include <string>

#include "hodt/brute_force.hpp"
#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/points.hpp"
#include "hodt/solve.hpp"
#include "exact/min_max_degree.hpp"
#include "generators.hpp"
#include "exact/factor_models.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// CPU time of this process: the work done, whatever else the machine runs.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Longest stretch of work without a progress point: about 12 ms was the worst
// seen on the machine this was written on, 33 ms on a slower CI machine (first
// order max-convex-edges, exact and auto, 60,000 DEM points). The wasm build runs
// 2 to 3 times slower than native: 50 ms here lets a caller cancel a solve in the
// browser within about 150 ms.
constexpr double kMaxGap = 0.050;

// A refusal must come before the work it refuses (about 0.5 s natively; the
// sanitizers' build runs three to four times slower).
#ifndef __has_feature  // (gcc before 14: it names AddressSanitizer __SANITIZE_ADDRESS__)
#define __has_feature(x) 0
#endif
#if defined(__SANITIZE_ADDRESS__) || __has_feature(address_sanitizer)
constexpr double kRefusalSeconds = 3.0;
#else
constexpr double kRefusalSeconds = 1.5;
#endif

struct Run {
  std::optional<Solution> solution;
  std::string refused;      // a LimitError's message
  bool cancelled = false;   // still running at the deadline
  double seconds = 0;       // CPU time
  double longest_gap = 0;   // CPU seconds without a progress call, start and end included
  uint32_t calls = 0;
};

// Solves with every progress point observed (none skipped by pacing), cancelling
// at the deadline.
Run run(const FirstOrder& fo, Objective o, Method m, double deadline, SolveOptions options = {}) {
  options.method = m;
  options.progress_interval_ms = 0;
  Run r;
  const double start = cpu_seconds();
  double last = start;
  options.progress = [&](double, double) {
    const double now = cpu_seconds();
    r.longest_gap = std::max(r.longest_gap, now - last);
    last = now;
    ++r.calls;
    return now - start < deadline;
  };
  try {
    r.solution = solve(fo, o, options);
  } catch (const LimitError& e) {
    r.refused = e.what();
  } catch (const Cancelled&) {
    r.cancelled = true;
  }
  const double end = cpu_seconds();
  r.longest_gap = std::max(r.longest_gap, end - last);
  r.seconds = end - start;
  return r;
}

FirstOrder wheel(int n, bool cone) { return first_order(delaunay(validate_points(wheel_points(n, cone)).xyz)); }

// What a result claims holds: its value is its triangulation's, and the optimum
// lies between value and bound (exact where optimal, against brute force if known).
void check_certified(const FirstOrder& fo, Objective o, const Solution& s, std::optional<double> optimum) {
  CHECK(s.value == evaluate(o, triangulate(fo, s.choice)));
  const bool min = info(o).sense == Sense::Min;
  if (s.optimal) {
    if (optimum) CHECK(s.value == *optimum);
    return;
  }
  REQUIRE(s.bound);
  CHECK((min ? *s.bound <= s.value : *s.bound >= s.value));
  if (optimum) {
    CHECK((min ? *s.bound <= *optimum : *s.bound >= *optimum));
    CHECK((min ? *optimum <= s.value : *optimum >= s.value));
  }
}

}  // namespace

TEST_CASE("wheels: every method answers with a certified value or a clear refusal, in seconds") {
  for (bool cone : {false, true})
    for (int n : {10, 30, 40, 46, 57, 87, 150}) {
      const FirstOrder fo = wheel(n, cone);
      for (Objective o : {Objective::MinMixedVertices, Objective::MinmaxDegree}) {
        std::optional<double> optimum;  // where brute force is quick
        if (fo.num_quads() <= 14) optimum = brute_force(fo, o).value;
        for (Method m : {Method::BruteForce, Method::Exact, Method::Approx, Method::Auto}) {
          CAPTURE(n);
          CAPTURE(cone);
          CAPTURE(std::string(info(o).id));
          CAPTURE(std::string(method_id(m)));
          // Brute force is exponential by design: up to 24 quads it runs (and may
          // be cancelled here), above it refuses.
          const Run r = run(fo, o, m, m == Method::BruteForce && fo.num_quads() > 14 ? 0.3 : 3);
          CHECK(r.longest_gap < kMaxGap);
          if (m == Method::BruteForce) {
            if (fo.num_quads() > 24) CHECK(r.refused.find("refuses m = ") != std::string::npos);
            else if (fo.num_quads() > 14 && r.cancelled) CHECK(r.seconds < 0.3 + kMaxGap);
            else {
              REQUIRE(r.solution);
              check_certified(fo, o, *r.solution, optimum);
            }
            continue;
          }
          CHECK_FALSE(r.cancelled);
          if (!r.refused.empty()) {
            CHECK(m == Method::Exact);  // auto and approx always answer
            CHECK(r.refused.find("the vertex at (0, 0) has ") != std::string::npos);
            continue;
          }
          REQUIRE(r.solution);
          check_certified(fo, o, *r.solution, optimum);
        }
      }
    }
}

TEST_CASE("exact refuses a vertex term over its budget, naming the vertex, before building it") {
  SolveOptions exact;
  exact.method = Method::Exact;
  const FirstOrder w57 = wheel(57, false), w87 = wheel(87, false), cone46 = wheel(46, true);
  REQUIRE(w57.num_quads() == 22);
  const double start = cpu_seconds();
  CHECK_THROWS_WITH_AS(solve(w57, Objective::MinMixedVertices, exact),
                       "exact: the vertex at (0, 0) has 22 flippable quads and 56 possible neighbours around it: its "
                       "term would need 2^22 entries; the exact limit is 2^20 (use --method approx)",
                       LimitError);
  CHECK_THROWS_WITH_AS(solve(w87, Objective::MinMixedVertices, exact),
                       doctest::Contains("has 30 flippable quads and 86 possible neighbours around it: its term would "
                                         "need 2^30 entries; the exact limit is 2^20"),
                       LimitError);
  CHECK_THROWS_WITH_AS(solve(w87, Objective::MinmaxDegree, exact),
                       doctest::Contains("the vertex at (0, 0) has 30 flippable quads around it: its term would need "
                                         "2^30 entries; the exact limit is 2^20"),
                       LimitError);
  // Few enough quads, but each entry classifies 45 neighbours: too slow to tabulate.
  CHECK_THROWS_WITH_AS(solve(cone46, Objective::MinMixedVertices, exact),
                       doctest::Contains("exact: the vertex at (0, 0) has 17 flippable quads and 45 possible neighbours "
                                         "around it: its term would take about 2^30.9 steps to tabulate (2^17 entries); "
                                         "the exact limit is 2^28"),
                       LimitError);
  CHECK(cpu_seconds() - start < 0.5);  // refused up front, not after filling 2^30 entries
}

TEST_CASE("auto and approx fall back with a certified bound, and say so") {
  for (int n : {57, 87, 150}) {
    const FirstOrder fo = wheel(n, false);
    CAPTURE(n);
    for (Method m : {Method::Approx, Method::Auto}) {
      SolveOptions options;
      options.method = m;
      const Solution mixed = solve(fo, Objective::MinMixedVertices, options);
      CHECK(mixed.method == "approx");
      CHECK(mixed.details.find("1 vertex terms too large to tabulate were relaxed") != std::string::npos);
      if (m == Method::Auto) CHECK(mixed.details.find("exact refused (exact: the vertex at (0, 0)") == 0);
      // The centre is the only interior vertex, and mixed whatever the choice
      // (heights alternate around it): relaxed, it counts as not mixed in the bound.
      CHECK(mixed.value == 1);
      CHECK(mixed.bound == 0);
      const Solution degree = solve(fo, Objective::MinmaxDegree, options);
      CHECK(degree.method == "approx");
      REQUIRE(degree.bound);
      CHECK(*degree.bound == degree_bounds(fo).lower);
      CHECK(degree.value <= 2 * *degree.bound);
      CHECK(degree.value == evaluate(Objective::MinmaxDegree, triangulate(fo, degree.choice)));
    }
  }
}

TEST_CASE("approx never refuses: a thick layer too wide for the DP falls back to a local search") {
  // Instances with interactions left after the roof dual (which fixes every quad
  // of a saddle grid, for both objectives).
  const FirstOrder frustrated = first_order(delaunay(frustrated_raster()));
  const FirstOrder jittered = first_order(delaunay(jittered_grid(30, 30, 0.35, 3)));
  SolveOptions options;
  options.method = Method::Approx;
  options.max_width = 0;  // every thick layer is wider
  for (const auto& c : {std::pair{Objective::MaxConvexEdges, &frustrated}, std::pair{Objective::MinMixedVertices, &jittered}}) {
    const Objective o = c.first;  // (clang 14 cannot capture a structured binding)
    const FirstOrder* fo = c.second;
    CAPTURE(std::string(info(o).id));
    const Solution s = solve(*fo, o, options);
    CAPTURE(s.details);
    CHECK(s.details.find("Baker's scheme refused (exact: a component of ") == 0);
    check_certified(*fo, o, s, std::nullopt);
  }
}

TEST_CASE("the exact DP refuses a wide decomposition without building it, and a memory budget") {
  // The engine itself (solve() first fixes this grid's quads by the roof dual).
  const FactorGraph saddle = factor_model(first_order(delaunay(saddle_grid(300))), Objective::MaxConvexEdges);
  const double start = cpu_seconds();
  CHECK_THROWS_WITH_AS(solve_exact(saddle), doctest::Contains("has a tree decomposition of width at least 21"), LimitError);
  CHECK(cpu_seconds() - start < kRefusalSeconds);  // the whole elimination took 4 s
  // Within the width cap but over the memory cap.
  const FirstOrder jittered = first_order(delaunay(jittered_grid(30, 30, 0.35, 2)));
  const FactorGraph g = factor_model(jittered, Objective::MaxConvexEdges);
  DpLimits limits;
  limits.max_table_bytes = 1024;
  CHECK_THROWS_WITH_AS(solve_exact(g, limits), doctest::Contains("; the memory cap is 1 MiB"), LimitError);
}

TEST_CASE("progress comes at least every 50 ms of work, in every solve") {
  struct Case {
    const char* name;
    FirstOrder fo;
  };
  const Case cases[] = {
      {"saddle grid 120", first_order(delaunay(saddle_grid(120)))},
      {"jittered grid 200", first_order(delaunay(jittered_grid(200, 200, 0.35, 3)))},
      {"dem 60000", first_order(delaunay(validate_points(dem_points(60000, 4)).xyz))},
      // The roof dual leaves 9081 quads too wide for min-degree and min-fill.
      {"frustrated raster 200", first_order(delaunay(frustrated_raster(200, 300, 750)))},
  };
  for (const Case& c : cases)
    for (const ObjectiveInfo& oi : objectives())
      for (Method m : {Method::Exact, Method::Approx, Method::Auto}) {
        if (m != Method::Auto && (oi.objective != Objective::MaxConvexEdges && oi.objective != Objective::MinMixedVertices &&
                                  oi.objective != Objective::MinmaxDegree))
          continue;  // polynomial objectives run the same exact algorithm for every method
        CAPTURE(std::string(c.name));
        CAPTURE(std::string(oi.id));
        CAPTURE(std::string(method_id(m)));
        Run r = run(c.fo, oi.objective, m, 20);
        // The work between progress points is the same in every run: a long
        // stretch in two runs is the solver's, in one the machine's (a 70 ms
        // stretch once, on the 60,000-point DEM, with another job on the
        // second core; 7 to 9 ms alone).
        if (r.longest_gap >= kMaxGap) r = run(c.fo, oi.objective, m, 20);
        CHECK_FALSE(r.cancelled);
        CHECK(r.calls > 0);
        CHECK(r.longest_gap < kMaxGap);
      }
}

TEST_CASE("cancelling from progress stops at once, and pacing keeps calls rare") {
  const FirstOrder grid = first_order(delaunay(saddle_grid(120)));
  const FirstOrder dem = first_order(delaunay(validate_points(dem_points(60000, 4)).xyz));
  // Each takes 0.1 to 0.3 s.
  for (Method m : {Method::Approx, Method::Auto}) {
    SolveOptions options;
    options.method = m;
    double asked = -1;
    const double start = cpu_seconds();
    options.progress = [&](double, double) {
      if (cpu_seconds() - start < 0.03) return true;
      asked = cpu_seconds();
      return false;
    };
    CHECK_THROWS_AS(solve(dem, Objective::MinMixedVertices, options), Cancelled);
    REQUIRE(asked >= 0);
    CHECK(cpu_seconds() - asked < kMaxGap);  // unwinding frees the tables
  }
  // Paced (the default 5 ms), a callback runs at every phase and then rarely.
  SolveOptions options;
  options.method = Method::Approx;
  uint32_t paced_calls = 0, every_call = 0;
  options.progress = [&](double, double) { return ++paced_calls, true; };
  const double start = cpu_seconds();
  solve(grid, Objective::MaxConvexEdges, options);
  const double seconds = cpu_seconds() - start;
  options.progress = [&](double, double) { return ++every_call, true; };
  options.progress_interval_ms = 0;
  solve(grid, Objective::MaxConvexEdges, options);
  CHECK(paced_calls > 0);
  CHECK(paced_calls < every_call);
  CHECK(paced_calls < 200 * seconds + 100);  // about one per 5 ms, plus the phases
}
