#include <algorithm>
#include <memory>

#include "higher_order/regions/fill_graph.hpp"
#include "higher_order/phases/phases.hpp"
#include "higher_order/regions/glue_regions.hpp"
#include "higher_order/regions/region_terms.hpp"
#include "mesh/mesh_of.hpp"

namespace hodt {

// Gluing: while a gap is left and every region not listed whole was read
// through its graph, those are glued in pairs (glue_regions.hpp) and read
// again: the bound tightens and the descent moves whole pairs. Each level is
// read in a second pairing too, none of the first's pairs (strips: shifted by
// one), whose descents leave other local optima.
std::optional<double> read_fill_graphs(KOrderRun& run, Incumbent& answer, const Progress& progress, uint32_t max_glue,
                                       uint32_t max_sweeps, std::optional<RegionDual>* unglued) {
  const Mesh& dt = run.dt;
  const Objective o = run.o;
  RegionEngine& engine = *run.engine;
  const Sense sense = run.sense;
  RegionDualLimits limits;
  limits.dual.progress = limits.dp.progress = progress;
  limits.model = engine.model_limits;
  limits.dp.max_table = run.budgets.pruned_dp_table;
  limits.dual.max_sweeps = max_sweeps;
  std::optional<double> bound;
  // One reading of R: its descents' best is offered, its bound tightens
  // `bound`; true when it proved the answer optimal.
  auto read = [&](Regions& R, const RegionTerms& terms, const std::string& glued, RegionDual& d) {
    add_states_of(R, dt, answer.triangulation());
    // (The engine's model is of its regions, but for those not listed whole.)
    d = region_dual(dt, R, o, engine.cand, terms, &answer.triangulation(), limits, &R == &engine.R ? &engine.model : nullptr);
    const std::string what = std::to_string(d.graphs) + " graphs" + glued;
    size_t best = d.found.size();
    for (size_t i = 0; i < d.found.size(); ++i)
      if (better(sense, d.values[i], best < d.found.size() ? d.values[best] : answer.value())) best = i;
    if (best < d.found.size())
      answer.offer(mesh_of(dt.coords, d.found[best]), d.values[best],
                   "descent over the regions' fill graphs from the dual (" + what + ")");
    if (d.bound) bound = bound ? tighter(sense, *bound, *d.bound) : d.bound;
    if (!d.proven) return false;
    const std::string why = "the dual read " + what + ", kept " + std::to_string(d.listed) +
                            " of their fills, and the dual proof over those proved " +
                            (d.optimum ? std::string("its optimum") : std::string("the answer")) + " optimal";
    if (d.optimum) {
      const double v = evaluate(o, *d.optimum);
      if (v != d.optimum_value) throw std::logic_error("order k: the fill graphs' model value differs from the triangulation's");
      answer.prove_with(std::move(*d.optimum), v, "the fill graphs' optimum", why);
    } else {
      answer.prove(why);
    }
    return true;
  };
  struct Level {
    Regions R;
    std::unique_ptr<RegionTerms> terms;  // (over R: the level stays where it is)
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
  };
  // R's regions read through graphs (as d says) glued in pairs, none of `avoid`;
  // nothing when no pair may glue.
  auto glue = [&](const Regions& R, const RegionDual& d, const std::vector<std::pair<uint32_t, uint32_t>>& avoid) {
    // Two regions side by side, with graphs of n_a and n_b partial fills over
    // l_a and l_b triangles, glue into a region whose sweep (fill_dp.hpp) keeps
    // about twice n_a n_b / max(l_a, l_b): pairs whose estimate, doubled, is
    // over the graphs' budget are not glued, nor regions of unlike lengths (a
    // short region beside a long one widens the sweep's frontier where they
    // overlap and gains little).
    const std::vector<uint32_t>& nodes = d.graph_nodes;
    auto estimate = [&](uint32_t a, uint32_t b) {
      return 2.0 * nodes[a] * nodes[b] /
             static_cast<double>(std::max(R.regions[a].delaunay_triangles.size(), R.regions[b].delaunay_triangles.size()));
    };
    auto level = std::make_unique<Level>();
    level->R = glue_pairs(
        dt, R,
        [&](uint32_t a, uint32_t b) {
          const double la = static_cast<double>(R.regions[a].delaunay_triangles.size());
          const double lb = static_cast<double>(R.regions[b].delaunay_triangles.size());
          return nodes[a] && nodes[b] && std::max(la, lb) <= 1.5 * std::min(la, lb) &&
                 2.0 * estimate(a, b) <= static_cast<double>(limits.max_states) &&
                 std::find(avoid.begin(), avoid.end(), std::pair{a, b}) == avoid.end();
        },
        &level->pairs);
    if (level->pairs.empty()) return std::unique_ptr<Level>();
    level->terms = std::make_unique<RegionTerms>(dt, level->R, o, &engine.cand);
    // The pair of the largest estimate is tried first: when its graph is over
    // the budget, the level would cost a whole dual for a weaker bound (the
    // terms' states decide the graphs' size too). And the level must fit the
    // graphs' total budget (else its last graphs would be left out, and the
    // bound with them).
    uint32_t trial = 0;
    double largest = -1, total = 0;
    for (const auto& [a, b] : level->pairs) {
      total += 2.0 * estimate(a, b);
      if (estimate(a, b) > largest) largest = estimate(a, b), trial = level->R.region_of_triangle[R.regions[a].delaunay_triangles[0]];
    }
    const double budget = static_cast<double>(std::max(limits.max_total, limits.max_total_per_point * dt.num_vertices()));
    if (total > budget / 2) return std::unique_ptr<Level>();
    if (!fill_graph(dt, engine.cand, *level->terms, trial, limits.max_states, progress)) level.reset();
    return level;
  };
  auto gap = [&] { return bound && better(sense, *bound, answer.value()); };
  RegionDual d;
  if (unglued && *unglued) {
    d = std::move(**unglued), bound = d.bound;
    unglued->reset();
  } else if (read(engine.R, engine.terms, "", d)) {
    return bound;
  }
  const Regions* parent = &engine.R;
  std::unique_ptr<Level> level;
  // (Each level costs a dual as large as the first.)
  auto gluable = [&] { return gap() && !d.relaxed && d.graphs >= 2 && d.graphs <= run.budgets.max_glued; };
  if (unglued && max_glue == 0 && gluable()) {
    d.found.clear(), d.values.clear();  // (the glue reads only the graphs' sizes: no triangulations held meanwhile)
    *unglued = std::move(d);
  }
  for (uint32_t times = 1; times <= max_glue && gluable(); ++times) {
    std::unique_ptr<Level> first = glue(*parent, d, {});
    if (!first) break;
    const std::string glued = ", the regions glued in pairs " + std::to_string(times) + " times";
    RegionDual d1;
    if (read(first->R, *first->terms, glued, d1)) return bound;
    if (gap())
      if (std::unique_ptr<Level> other = glue(*parent, d, first->pairs)) {
        RegionDual d2;
        if (read(other->R, *other->terms, glued + " (another pairing)", d2)) return bound;
      }
    level = std::move(first);
    parent = &level->R;
    d = std::move(d1);
  }
  return bound;
}

}  // namespace hodt
