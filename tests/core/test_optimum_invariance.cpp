// Metamorphic checks on instances too large for brute force (25 to 90 points,
// where the exact engine, the dual proofs and the quads path all answer): a
// proven optimum is a property of the terrain, not of how it was given. The same
// instance swapped (x <-> y), mirrored, turned by a half turn, scaled by 2 (x, y
// and z: exact) or shuffled goes through other vertex numbers, other regions'
// orders and other tree decompositions; no answer may beat an optimum proven on
// another, and no bound may pass it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "hodt/delaunay.hpp"
#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "hodt/points.hpp"
#include "hodt/solve.hpp"
#include "generators.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

enum class Change { None, Swap, Mirror, HalfTurn, Double, Shuffle };
constexpr Change kChanges[] = {Change::None, Change::Swap, Change::Mirror, Change::HalfTurn, Change::Double, Change::Shuffle};
const char* name(Change c) {
  static const char* const names[] = {"as given", "swapped", "mirrored", "turned", "doubled", "shuffled"};
  return names[static_cast<int>(c)];
}

std::vector<double> changed(std::vector<double> p, Change c, uint64_t seed) {
  const size_t n = p.size() / 3;
  for (size_t i = 0; i < n; ++i) {
    double &x = p[3 * i], &y = p[3 * i + 1];
    if (c == Change::Swap) std::swap(x, y);
    if (c == Change::Mirror) x = -x;
    if (c == Change::HalfTurn) x = -x, y = -y;
    if (c == Change::Double) x *= 2, y *= 2, p[3 * i + 2] *= 2;
  }
  return c == Change::Shuffle ? shuffled(std::move(p), seed) : p;
}

// Swap, mirror and turn change the lexicographic order of the points, so on
// cocircular input they change the symbolic perturbation, and with it which
// triangles are k-OD: a different problem. Doubling and shuffling keep it.
bool keeps_problem(Change c, bool cocircular) {
  return !cocircular || c == Change::None || c == Change::Double || c == Change::Shuffle;
}

// What doubling does to a value: lengths and radii double, areas quadruple.
double doubled(Objective o) {
  switch (o) {
    case Objective::MinTotalEdgeLength:
    case Objective::MinmaxEdgeEnclosingCircle: return 2;
    case Objective::MinmaxTriangleArea: return 4;
    default: return 1;
  }
}

struct Instance {
  std::vector<double> xyz;
  bool cocircular;
};

Instance instance(uint64_t seed) {
  Rng r(seed * 7919);
  switch (seed % 5) {
    case 0: return {dem_points(25 + r.below(65), seed), false};
    case 1: return {uniform_points(25 + r.below(65), seed), false};
    case 2: return {grid_points(5 + r.below(4), 5 + r.below(4), seed, true), true};  // (equal heights)
    case 3: return {jittered_grid(6 + r.below(3), 6 + r.below(3), 0.02, seed), false};
    default: return {grid_points(5 + r.below(5), 5 + r.below(4), seed), true};
  }
}

struct Answer {
  double value, bound;
  bool optimal;
};

}  // namespace

TEST_CASE("optimum invariant under exact changes of the input: swapped, mirrored, turned, doubled, shuffled (k = 1..4)") {
  int proven = 0, compared = 0;
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    const Instance in = instance(seed);
    for (uint32_t k = 1; k <= 4; ++k)
      for (const ObjectiveInfo& oi : objectives()) {
        const bool max = oi.sense == Sense::Max;
        std::vector<std::pair<Change, Answer>> answers;
        for (const Change c : kChanges) {
          if (!keeps_problem(c, in.cocircular)) continue;
          const FirstOrder fo = first_order(delaunay(validate_points(changed(in.xyz, c, seed)).xyz));
          SolveOptions options;
          options.order = k;
          const Solution s = solve(fo, oi.objective, options);
          const double f = c == Change::Double ? doubled(oi.objective) : 1;
          answers.push_back({c, {s.value / f, (s.bound ? *s.bound : s.value) / f, s.optimal}});
        }
        auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); };
        auto beats = [&](double x, double optimum) { return !same(x, optimum) && (max ? x > optimum : x < optimum); };
        // (no structured bindings here: clang 14 lets no lambda, INFO's included, capture one)
        for (const auto& ca : answers) {
          const Change c = ca.first;
          const Answer& a = ca.second;
          if (!a.optimal) continue;
          ++proven;
          for (const auto& db : answers) {
            const Change d = db.first;
            const Answer& b = db.second;
            ++compared;
            INFO("seed ", seed, " k ", k, " ", oi.id, ": optimum ", a.value, " ", name(c), "; ", name(d), ": value ", b.value,
                 " bound ", b.bound, " optimal ", b.optimal);
            CHECK_FALSE(beats(b.value, a.value));
            CHECK_FALSE(beats(a.value, b.bound));  // (the bound on the optimum's side: no triangulation is past it)
          }
        }
      }
  }
  MESSAGE(proven, " proven optima, ", compared, " comparisons");
  CHECK(proven > 3000);
}
