#include <cmath>

#include "higher_order/bounds/star_bound.hpp"
#include "higher_order/bounds/star_decode.hpp"
#include "higher_order/phases/phases.hpp"
#include "higher_order/search/fan_windows.hpp"
#include "higher_order/search/flip_search.hpp"
#include "mesh/mesh_of.hpp"

namespace hodt {

// The bound from the vertices' stars (star_bound.hpp) and the fans its
// multipliers favour, made to agree (star_decode.hpp), then flipped: where the
// relaxation is nearly tight, this reaches far past what flips and descents
// do. Sweeps four ways, then repairs of the best at hand while they improve it;
// then windows of 25 vertices, each at its best with the rest kept
// (fan_windows.hpp), while they improve it, then larger ones.
void search_stars(KOrderRun& run) {
  const Mesh& dt = run.dt;
  const Objective o = run.o;
  const Sense sense = run.sense;
  const Candidates& cand = run.engine->cand;
  const Progress& progress = run.proving;
  double bound = run.bound();
  struct Start {
    Mesh triangulation;
    double value;
  };
  auto flipped = [&](const std::vector<Tri>& tris) {
    Mesh m = mesh_of(dt.coords, tris);
    improve_by_flips(m, dt, run.k, o, progress, run.shared.memo);
    const double v = evaluate(o, m);
    return Start{std::move(m), v};
  };
  Start best{run.answer.triangulation(), run.answer.value()};
  bool decoded = false, windowed = false;
  auto adopt = [&](Start s) {
    if (better(sense, s.value, best.value)) {
      best = std::move(s), decoded = true;
      return true;
    }
    return false;
  };
  auto decode = [&](const StarDecoder& d) {
    for (const std::vector<Tri>& tris : d.sweeps()) adopt(flipped(tris));
    for (int round = 0; round < 8 && better(sense, bound, best.value); ++round) {
      const auto repaired = d.repair(best.triangulation);
      if (!repaired || !adopt(flipped(*repaired))) break;
    }
  };
  // Descent from s by windows of `size` vertices while they improve it, at
  // most `passes` passes (and the budget's placements in all), each with its tiles placed anew (a
  // move across one pass's tile borders may lie inside the next's); true if it
  // improved s.
  WindowLimits windows;
  windows.progress = progress;
  uint32_t placement = 0;  // (the passes so far)
  auto descend = [&](Start& s, uint32_t size, uint32_t passes) {
    windows.per_window = size;
    bool improved = false;
    for (uint32_t pass = 0; pass < passes && placement < run.budgets.fan_window_placements && better(sense, bound, s.value); ++pass) {
      windows.enough = std::fabs(bound - s.value);  // (then the value meets the bound)
      windows.placement = placement++;
      const auto w = improve_by_windows(dt, o, cand, s.triangulation, windows);
      if (!w) break;
      Start t = flipped(*w);
      if (!better(sense, t.value, s.value)) break;
      s = std::move(t), improved = true;
    }
    return improved;
  };
  if (better(sense, bound, best.value)) {
    StarBoundLimits stars;
    stars.progress = progress;
    stars.decode = true;
    stars.known_bound = bound;
    // (Tiles of many decode one by one, the rest held at the best at hand.)
    stars.start = &best.triangulation;
    stars.decoded_tile = decode;
    const auto b = star_bound(dt, o, cand, best.value, stars);
    if (b && better(sense, bound, b->bound)) {
      bound = b->bound;
      run.answer.tighten(bound, "the vertices' stars");
    }
    if (b && b->decoder) decode(*b->decoder);
    // Then windows of each size in turn while they improve it.
    for (const uint32_t size : run.budgets.fan_window_sizes)
      windowed = descend(best, size, run.budgets.fan_window_placements) || windowed;
  }
  if (decoded || windowed) {
    const std::string by = decoded && windowed ? "a triangulation read off the stars, then descent by windows of fans"
                           : decoded           ? "a triangulation read off the stars"
                                               : "descent by windows of fans";
    run.answer.offer(std::move(best.triangulation), best.value, by);
  }
}

}  // namespace hodt
