#include "hodt/brute_force.hpp"

#include <chrono>
#include <cmath>

#include "hodt/error.hpp"
#include "hodt/progress.hpp"
#include "tuning/budgets.hpp"

namespace hodt {
namespace {

void check_size(const FirstOrder& fo) {
  if (fo.num_quads() > kBudgets.brute_force_max_quads)
    throw LimitError("brute force enumerates 2^m triangulations and refuses m = " +
                     std::to_string(fo.num_quads()) + " flippable quads (at most " +
                     std::to_string(kBudgets.brute_force_max_quads) + "); use --method exact or auto");
}

// Visits every choice in Gray code order, flipping one quad per step.
template <class Visit>
void gray_walk(const FirstOrder& fo, Visit visit) {
  Mesh mesh = fo.base;
  Choice choice(fo.num_quads(), 0);
  visit(mesh, choice);
  const uint64_t total = uint64_t(1) << fo.num_quads();
  for (uint64_t i = 1; i < total; ++i) {
    uint32_t q = 0;
    while (!((i >> q) & 1)) ++q;  // the lowest set bit of i is the quad to flip
    flip_edge(mesh, fo.quads[q].edge);
    choice[q] ^= 1;
    visit(mesh, choice);
  }
}

}  // namespace

Solution brute_force(const FirstOrder& fo, Objective objective, const Progress& progress) {
  check_size(fo);
  const auto t0 = std::chrono::steady_clock::now();
  const Sense sense = info(objective).sense;
  Solution s;
  s.objective = objective;
  s.method = "brute-force";
  bool first = true;
  uint32_t best_flips = 0;
  const double total = std::ldexp(1.0, static_cast<int>(fo.num_quads()));
  double done = 0;
  gray_walk(fo, [&](const Mesh& mesh, const Choice& choice) {
    report(progress, done, total);  // each step measures a whole triangulation: never cheap
    ++done;
    const double v = evaluate(objective, mesh);
    const uint32_t flips = count_flipped(choice);
    if (first) s.delaunay_value = v;
    if (first || better(sense, v, s.value) || (v == s.value && flips < best_flips)) {
      s.value = v;
      s.choice = choice;
      best_flips = flips;
      first = false;
    }
  });
  s.optimal = true;
  s.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

std::vector<std::array<double, kNumObjectives>> enumerate_all(const FirstOrder& fo) {
  check_size(fo);
  std::vector<std::array<double, kNumObjectives>> out(size_t(1) << fo.num_quads());
  gray_walk(fo, [&](const Mesh& mesh, const Choice& choice) {
    size_t index = 0;
    for (size_t q = 0; q < choice.size(); ++q) index |= size_t(choice[q]) << q;
    out[index] = evaluate_all(mesh);
  });
  return out;
}

}  // namespace hodt
