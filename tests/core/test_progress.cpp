// Progress as a person reads it: named phases, a fraction that never goes back
// within a phase whatever the solvers' counts do, an estimate of the time left
// only where the phase knows its size, and cancellation through it.
#include <doctest/doctest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "hodt/progress.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"
#include "cli/cli_progress.hpp"
#include "generators.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// Every point a phased Progress passes on (interval 0: all of them).
struct Recorder {
  std::vector<ProgressPoint> points;
  Progress progress() {
    return phased([this](const ProgressPoint& p) { return points.push_back(p), true; }, 0);
  }
  // Fails unless each phase's fraction is non-decreasing over the whole run, in [0, 1].
  void check_monotone() const {
    std::map<Phase, double> last;
    for (const ProgressPoint& p : points) {
      CAPTURE(std::string(phase_name(p.phase)));
      CHECK(p.fraction >= 0);
      CHECK(p.fraction <= 1);
      if (last.count(p.phase)) CHECK(p.fraction >= last[p.phase]);
      last[p.phase] = p.fraction;
    }
  }
};

}  // namespace

TEST_CASE("each phase has one name of its own, in words a user knows") {
  std::set<std::string> names;
  for (size_t i = 0; i < kNumPhases; ++i) names.insert(std::string(phase_name(static_cast<Phase>(i))));
  CHECK(names.size() == kNumPhases);
  CHECK(phase_name(Phase::Reading) == "reading");
  CHECK(phase_name(Phase::FindingRegions) == "finding the regions");
  CHECK(phase_name(Phase::SolvingExactly) == "solving exactly");
  CHECK(phase_name(Phase::ProvingBound) == "proving a bound");
  CHECK(phase_name(Phase::Writing) == "writing");
}

TEST_CASE("a solver that restarts its count moves its phase on, never back") {
  Recorder r;
  const Progress searching = in_phase(r.progress(), Phase::Searching);
  for (int loop = 0; loop < 4; ++loop)  // four loops of different lengths, each from 0
    for (int i = 0; i <= 10 * (loop + 1); ++i) report(searching, i, 10 * (loop + 1));
  r.check_monotone();
  REQUIRE(!r.points.empty());
  CHECK(r.points.front().phase == Phase::Searching);
  CHECK(!r.points.back().sized);  // its size unknown: each loop takes a tenth of what is left
  CHECK(r.points.back().fraction == doctest::Approx(1 - 0.9 * 0.9 * 0.9 * 0.9));
  CHECK(r.points.back().fraction < 1);
}

TEST_CASE("a phase whose driver knows its loops is sized until it has more") {
  Recorder r;
  const Progress exactly = in_phase(r.progress(), Phase::SolvingExactly, 2);
  report(exactly, 5, 10);
  CHECK(r.points.back().fraction == doctest::Approx(0.25));  // half of the first of two shares
  report(exactly, 10, 10);
  report(exactly, 0, 4);  // the second loop
  CHECK(r.points.back().fraction == doctest::Approx(0.5));
  report(exactly, 2, 4);
  CHECK(r.points.back().fraction == doctest::Approx(0.75));
  CHECK(r.points.back().sized);
  report(exactly, 0, 7);  // a third: more than the driver said
  CHECK(!r.points.back().sized);
  report(exactly, 7, 7);
  CHECK(r.points.back().fraction == doctest::Approx(0.75 + 0.25 / 10));
  r.check_monotone();
}

TEST_CASE("phases: a phase met again goes on from where it was; a held phase is not renamed") {
  Recorder r;
  const Progress run = r.progress();
  const Progress finding = in_phase(run, Phase::FindingRegions), proving = in_phase(run, Phase::ProvingBound);
  report(finding, 8, 10);
  report(proving, 3, 10);
  report(finding, 1, 10);  // a new loop of the phase met again
  r.check_monotone();
  CHECK(r.points.back().phase == Phase::FindingRegions);
  CHECK(r.points.back().fraction >= r.points.front().fraction);
  // A nested solve held as searching: its own drivers' phases do not show.
  const Progress held = hold_in_phase(run, Phase::Searching);
  report(in_phase(held, Phase::SolvingExactly), 1, 2);
  CHECK(r.points.back().phase == Phase::Searching);
  // A plain callback has no phases: in_phase leaves it as it is.
  std::vector<std::pair<double, double>> raw;
  const Progress plain = [&](double done, double total) { return raw.emplace_back(done, total), true; };
  report(in_phase(plain, Phase::Searching), 3, 7);
  CHECK(raw == std::vector<std::pair<double, double>>{{3, 7}});
}

TEST_CASE("pacing passes each new phase and loop at once and the rest at most every interval") {
  std::vector<Phase> seen;
  const Progress run = phased([&](const ProgressPoint& p) { return seen.push_back(p.phase), true; }, 60'000);
  for (int i = 0; i < 1000; ++i) report(in_phase(run, Phase::Searching), i, 1000);
  for (int loop = 0; loop < 2; ++loop)
    for (int i = 0; i < 1000; ++i) report(in_phase(run, Phase::ProvingBound), i, 1000);
  CHECK(seen == std::vector<Phase>{Phase::Searching, Phase::ProvingBound, Phase::ProvingBound});
}

TEST_CASE("cancelling through a phased progress throws Cancelled") {
  const Progress stop = phased([](const ProgressPoint&) { return false; });
  CHECK_THROWS_AS(report(in_phase(stop, Phase::Searching), 0, 1), Cancelled);
  const Terrain t = Terrain::from_points(uniform_points(300, 3));
  SolveOptions options;
  options.progress = stop;
  CHECK_THROWS_AS(solve(t.structure(), Objective::MaxConvexEdges, options), Cancelled);
}

TEST_CASE("the time left: only for a sized phase, after 2 s and 5% of its work") {
  ProgressPoint p;
  p.phase = Phase::SolvingExactly;
  p.sized = true;
  p.fraction = 0.25, p.seconds = 4;
  REQUIRE(seconds_left(p));
  CHECK(*seconds_left(p) == doctest::Approx(12));
  CHECK(CliProgress::line(p, "min-local-minima, order 4") ==
        "solving exactly (min-local-minima, order 4): 25%, about 12 s left");
  p.seconds = 1.5;
  CHECK(!seconds_left(p));  // too soon
  CHECK(CliProgress::line(p, "x") == "solving exactly (x): 25%");
  p.seconds = 10, p.fraction = 0.04;
  CHECK(!seconds_left(p));  // too little done
  p.fraction = 0.5, p.sized = false;
  CHECK(!seconds_left(p));  // its size unknown
  CHECK(CliProgress::line(p, "x") == "solving exactly (x): 10 s so far");
}

TEST_CASE("real solves report named phases, each one's fraction never going back") {
  const Terrain t = Terrain::from_points(dem_points(900, 5));
  struct Case {
    uint32_t order;
    Method method;
    Objective objective;
    std::set<Phase> expected;  // (at least these)
  };
  const std::vector<Case> cases = {
      {1, Method::Exact, Objective::MinMixedVertices, {Phase::SolvingExactly, Phase::Measuring}},
      {1, Method::Approx, Objective::MaxConvexEdges, {Phase::Approximating}},
      {3, Method::Auto, Objective::MinMixedVertices, {Phase::FindingRegions, Phase::Measuring}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.order);
    CAPTURE(std::string(info(c.objective).id));
    Recorder r;
    SolveOptions options;
    options.order = c.order;
    options.method = c.method;
    options.progress = r.progress();
    solve(t.structure(), c.objective, options);
    r.check_monotone();
    std::set<Phase> phases;
    for (const ProgressPoint& p : r.points) phases.insert(p.phase);
    for (Phase p : c.expected) CHECK(phases.count(p));
    CHECK(!phases.count(Phase::Solving));  // every step of the engine is named
  }
  // A plain (done, total) callback gets each phase's fraction as (fraction, 1).
  SolveOptions options;
  options.order = 3;
  double last = -1;
  bool one = true;
  options.progress = [&](double done, double total) {
    one = one && total == 1 && done >= 0 && done <= 1;
    last = done;
    return true;
  };
  solve(t.structure(), Objective::MinMixedVertices, options);
  CHECK(one);
  CHECK(last >= 0);
}

TEST_CASE("brute force knows its size: a sized phase whose fraction reaches the end") {
  const Terrain t = Terrain::from_points(uniform_points(32, 3));
  REQUIRE(t.structure().num_quads() <= 16);  // (a short brute force)
  Recorder r;
  SolveOptions options;
  options.method = Method::BruteForce;
  options.progress = r.progress();
  solve(t.structure(), Objective::MinMixedVertices, options);
  r.check_monotone();
  double reached = 0;
  for (const ProgressPoint& p : r.points)
    if (p.phase == Phase::SolvingExactly) {
      CHECK(p.sized);
      reached = p.fraction;
    }
  CHECK(reached > 0.99);
}
