#include "higher_order/bounds/region_dual.hpp"

#include <algorithm>
#include <random>

#include "hodt/error.hpp"
#include "hodt/measures.hpp"
#include "higher_order/regions/fill_graph.hpp"
#include "higher_order/regions/region_model.hpp"
#include "mesh/mesh_of.hpp"

namespace hodt {

namespace {

// A region's fills as an implicit factor over its items' variables (min form).
// Items with one entry have no variable: their costs stay 0.
struct RegionFactor final : ImplicitFactor {
  FillGraph graph;                 // its arc costs in min form
  double offset = 0;               // less the Delaunay fill's own terms (the model counts those)
  std::vector<uint32_t> item_of;   // per scope position, its item in the graph
  mutable std::vector<std::vector<double>> costs, marginals;

  double least(const std::vector<std::vector<double>>& scope_costs,
               std::vector<std::vector<double>>* scope_marginals) const override {
    const double v = graph.least(item_costs(scope_costs), scope_marginals ? &marginals : nullptr) + offset;
    if (scope_marginals) {
      scope_marginals->resize(item_of.size());
      for (size_t j = 0; j < item_of.size(); ++j) {
        (*scope_marginals)[j] = marginals[item_of[j]];
        for (double& m : (*scope_marginals)[j]) m += offset;
      }
    }
    return v;
  }
  // The same with a least fill and its entries (per item of the graph).
  double best(const std::vector<std::vector<double>>& scope_costs, std::vector<Tri>& fill,
              std::vector<uint32_t>* entries = nullptr) const {
    return graph.least(item_costs(scope_costs), nullptr, &fill, entries) + offset;
  }
  // Costs per scope position, as the graph reads them (per item; 0 for items without a variable).
  const std::vector<std::vector<double>>& item_costs(const std::vector<std::vector<double>>& scope_costs) const {
    costs.resize(graph.entries.size());
    for (size_t i = 0; i < costs.size(); ++i) costs[i].assign(graph.entries[i].size(), 0.0);
    for (size_t j = 0; j < item_of.size(); ++j) costs[item_of[j]] = scope_costs[j];
    return costs;
  }
};

// Block coordinate descent over the model with its regions' graphs: each
// variable in turn takes its best state for the others' (min form), each region
// read through its graph its best fill for the terms its entries meet, until
// nothing improves. (A term over two items of one region reads the other's
// current entry: a step may then not improve, and the passes are bounded.)
struct Descent {
  const StateGraph& g;
  const std::vector<RegionFactor>& factors;  // per region (empty scope: none)
  const std::vector<uint32_t>& regions;      // those with a graph
  double sign;
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> reads;  // per variable: (factor, position)
  std::vector<uint8_t> in_block;

  Descent(const StateGraph& graph, const std::vector<RegionFactor>& f, const std::vector<uint32_t>& r)
      : g(graph), factors(f), regions(r), sign(graph.sense == Sense::Min ? 1.0 : -1.0),
        reads(graph.domain.size()), in_block(graph.domain.size(), 0) {
    for (uint32_t fi = 0; fi < g.factors.size(); ++fi)
      for (uint32_t j = 0; j < g.factors[fi].scope.size(); ++j) reads[g.factors[fi].scope[j]].push_back({fi, j});
    for (uint32_t r : regions)
      for (uint32_t x : factors[r].scope) in_block[x] = 1;
  }

  // Variable x in each of its states, the others as they are (min form).
  std::vector<double> local(uint32_t x, std::vector<uint32_t>& state) const {
    std::vector<double> v(g.domain[x]);
    const uint32_t keep = state[x];
    for (uint32_t s = 0; s < g.domain[x]; ++s) {
      state[x] = s;
      double t = g.unary[x][s];
      for (auto [fi, j] : reads[x]) {
        const StateFactor& f = g.factors[fi];
        size_t idx = 0, stride = 1;
        for (size_t i = 0; i < f.scope.size(); ++i) idx += stride * f.project[i][state[f.scope[i]]], stride *= f.dims[i];
        t += f.table[idx];
      }
      v[s] = sign * t;
    }
    state[x] = keep;
    return v;
  }

  // Runs from `state` (per variable); fills: per region with a graph, its fill.
  // seed: the regions in a shuffled order (0: as given).
  void run(std::vector<uint32_t>& state, std::vector<std::vector<Tri>>& fills, uint32_t seed = 0) const {
    std::vector<uint32_t> order = regions;
    if (seed) std::shuffle(order.begin(), order.end(), std::mt19937(seed));
    for (int pass = 0; pass < 50; ++pass) {
      bool moved = false;
      for (uint32_t x = 0; x < g.domain.size(); ++x) {
        if (in_block[x] || g.domain[x] < 2) continue;
        const std::vector<double> v = local(x, state);
        const uint32_t s = static_cast<uint32_t>(std::min_element(v.begin(), v.end()) - v.begin());
        if (v[s] < v[state[x]]) state[x] = s, moved = true;
      }
      for (uint32_t r : order) {
        const RegionFactor& f = factors[r];
        std::vector<std::vector<double>> costs(f.scope.size());
        for (size_t j = 0; j < f.scope.size(); ++j) costs[j] = local(f.scope[j], state);
        // Its best fill, and its best with the entries it has now: the first
        // when strictly better (no cycling), else the second (the others see
        // nothing change; its own terms may improve).
        std::vector<uint32_t> entries;
        std::vector<Tri> free, kept;
        const double best = f.best(costs, free, &entries);
        for (size_t j = 0; j < f.scope.size(); ++j)
          for (uint32_t e = 0; e < costs[j].size(); ++e)
            if (e != state[f.scope[j]]) costs[j][e] = INFINITY;
        const double now = f.best(costs, kept);
        if (!(best < now)) {
          fills[r] = std::move(kept);
          continue;
        }
        fills[r] = std::move(free);
        for (size_t j = 0; j < f.scope.size(); ++j) state[f.scope[j]] = entries[f.item_of[j]];
        moved = true;
      }
      if (!moved) break;
    }
  }
};

// Whether a k-OD triangulation beats `target` (an integer): the graphs pruned
// to the fills whose bound allows one, those listed, and the dual proof (its
// pruning and exact DP) over the model, now whole. Not proven when a list or
// the DP is over its budget; `better`, when proven, is an optimum.
struct Probe {
  bool proven = false;
  std::optional<Mesh> better;
  double better_value = 0;  // (the model's)
  uint64_t listed = 0;
};

// listed: the regions, those read through graphs listed anew here; model: its
// model from the last target (or the caller's, or nothing), updated here.
Probe probe(const Mesh& dt, Regions& listed, Objective o, const std::vector<RegionFactor>& factors,
            const std::vector<uint32_t>& region_of_factor, const std::vector<uint8_t>& changed, const DualProof& proof,
            double target, const RegionDualLimits& limits, std::optional<RegionModel>& model) {
  Probe out;
  const Sense sense = info(o).sense;
  const double ub = (sense == Sense::Min ? 1.0 : -1.0) * target;  // (min form)
  for (size_t i = 0; i < region_of_factor.size(); ++i) {
    const uint32_t r = region_of_factor[i];
    const RegionFactor& f = factors[r];
    const auto red = proof.implicit_reduced(i);
    if (!red) return out;
    const auto through = f.graph.through(f.item_costs(red->costs));
    if (!through) return out;
    // Integer values: a fill can be in a better triangulation only if its bound is at most ub - 1.
    std::vector<uint8_t> kept(through->size());
    for (size_t a = 0; a < kept.size(); ++a) kept[a] = red->offset + f.offset + (*through)[a] <= ub - 1;
    const uint64_t room = std::min(limits.max_listed, limits.max_listed_total - out.listed);
    // Every fill when few are left (often none), else the least fill per
    // combination of entries (what the regions beside see, each at its best).
    auto fills = f.graph.fills(kept, room);
    // (Partial combinations beyond a few per fill listed: a long region's,
    // whose combinations are past counting.)
    if (!fills) fills = f.graph.best_by_entries(kept, room, std::min<uint64_t>(4 * room, limits.max_states));
    if (!fills) return out;
    out.listed += fills->size();
    auto& states = listed.regions[r].states;
    states.resize(1);  // (the Delaunay fill stays first)
    for (const auto& fill : *fills)
      if (fill != states[0]) states.push_back(fill);
    listed.regions[r].complete = true;
  }
  listed.incomplete = 0;
  model = model ? update_region_model(std::move(*model), dt, listed, o, changed, limits.model, limits.dual.progress)
                : region_model(dt, listed, o, limits.model, limits.dual.progress);
  const DualProof again(model->graph, limits.dual, target);
  if (!again.applies()) return out;
  const DualProof::Proof p = again.prove(target, limits.dp);
  out.proven = p.proven;
  if (p.proven && p.better) {
    out.better = listed.triangulation(dt, model->region_states(*p.better));
    out.better_value = p.better_value;
  }
  return out;
}

// RegionDual::proven, above, with `best` the best value at hand (the start's
// or one found). A target one unit short of the bound prunes the most: each
// such target proven unbeaten takes the bound one unit closer, and an
// optimum found is one. Then the best at hand itself: its proof lists other
// fills and may fit where the first target's did not.
// The targets share one copy of the regions and one model, updated in turn.
void prove(const Mesh& dt, const Regions& R, Objective o, const std::vector<RegionFactor>& factors,
           const std::vector<uint32_t>& region_of_factor, const DualProof& proof, double best,
           const RegionDualLimits& limits, const RegionModel* model_of_R, RegionDual& out) {
  const Sense sense = info(o).sense;
  Regions listed = R;
  std::optional<RegionModel> model;
  if (model_of_R) model = *model_of_R;
  std::vector<uint8_t> changed(R.regions.size(), 0);
  for (uint32_t r : region_of_factor) changed[r] = 1;
  for (int round = 0;; ++round) {
    const double short_of_bound = sense == Sense::Min ? *out.bound + 1 : *out.bound - 1;
    const bool last = round >= static_cast<int>(limits.short_rounds) || !better(sense, short_of_bound, best);
    const double target = last ? best : short_of_bound;
    Probe p = probe(dt, listed, o, factors, region_of_factor, changed, proof, target, limits, model);
    out.listed = p.listed;
    if (!p.proven) return;
    if (p.better || last) {
      out.proven = true;
      out.optimum = std::move(p.better);
      out.optimum_value = p.better_value;
      return;
    }
    out.bound = target;  // (no triangulation beats it)
    ++out.tightened;
  }
}

// The model with the regions not listed whole read through their graphs:
// per item a variable (a view of one item), per region an implicit factor.
struct GraphModel {
  RegionModel model;
  std::vector<RegionFactor> factors;       // per region (with a graph: a scope)
  std::vector<uint32_t> region_of_factor;  // the regions with a graph
  std::vector<uint8_t> has_graph;          // per region
  uint32_t relaxed = 0;                    // regions not listed whole without one
  std::vector<const ImplicitFactor*> implicit() const {
    std::vector<const ImplicitFactor*> out;
    for (uint32_t r : region_of_factor) out.push_back(&factors[r]);
    return out;
  }
};

// What a view of one item needs of a fill (region_model reads a vertex item's
// fan and an edge item's apex only): the triangles at the item's vertices. A
// long region's fills are hundreds of triangles, and it has hundreds of items.
std::vector<Tri> near_item(const std::vector<Tri>& fill, const Tri& item) {
  const bool vertex = item == RegionTerms::vertex_item(item[1]);
  if (!vertex && item != RegionTerms::edge_item(item[1], item[2])) return fill;
  const uint32_t a = item[1], b = vertex ? item[1] : item[2];
  std::vector<Tri> out;
  for (const Tri& t : fill)
    if (std::find(t.begin(), t.end(), a) != t.end() || std::find(t.begin(), t.end(), b) != t.end()) out.push_back(t);
  return out;
}

// Nothing if no region not listed whole has a graph that fits. model_of_R: as
// region_dual's (the model is its update, when given).
std::optional<GraphModel> graph_model(const Mesh& dt, const Regions& R, Objective o, const Candidates& cand,
                                      const RegionTerms& terms, const RegionDualLimits& limits,
                                      const RegionModel* model_of_R = nullptr) {
  const double sign = info(o).sense == Sense::Min ? 1.0 : -1.0;
  std::vector<std::optional<FillGraph>> graphs(R.regions.size());
  std::vector<std::vector<RegionView>> views(R.regions.size());
  // Smallest regions first; every region gets a small budget, then (when few
  // are left) the rest a large one each, while the total lasts: many hopeless
  // regions would otherwise eat the time of the few that fit.
  std::vector<uint32_t> order;
  for (uint32_t r = 0; r < R.regions.size(); ++r)
    if (!R.regions[r].complete) order.push_back(r);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return R.regions[a].delaunay_triangles.size() < R.regions[b].delaunay_triangles.size();
  });
  uint64_t used = 0;
  const uint64_t max_total = std::max(limits.max_total, limits.max_total_per_point * dt.num_vertices());
  std::vector<uint32_t> left;
  for (uint32_t r : order) {
    if (used < max_total)
      graphs[r] = fill_graph(dt, cand, terms, r, std::min(limits.first_states, max_total - used),
                             limits.dual.progress, &used);
    if (!graphs[r]) left.push_back(r);
  }
  // (Many left: the second pass goes on while its regions fit, smallest first;
  // a run of failures says the rest are hopeless.)
  uint32_t failures = 0;
  for (uint32_t r : left) {
    if (used >= max_total || (left.size() > limits.max_second && failures >= limits.max_second_failures)) break;
    graphs[r] = fill_graph(dt, cand, terms, r, std::min(limits.max_states, max_total - used), limits.dual.progress, &used);
    failures = graphs[r] ? 0 : failures + 1;
  }
  GraphModel m;
  m.has_graph.assign(R.regions.size(), 0);
  for (uint32_t r : order) {
    if (!graphs[r]) {
      ++m.relaxed;
      continue;
    }
    m.has_graph[r] = 1;
    // Its own terms from the implicit factor: the model reads the Delaunay fill
    // for them (a constant), each item from the fills that stand for its entries.
    views[r].push_back({{}, {R.regions[r].states[0]}});
    auto reps = graphs[r]->representatives();
    for (size_t i = 0; i < reps.size(); ++i) {
      for (auto& fill : reps[i]) fill = near_item(fill, graphs[r]->items[i]);
      views[r].push_back({{graphs[r]->items[i]}, std::move(reps[i])});
    }
  }
  if (m.relaxed == order.size()) return std::nullopt;
  if (model_of_R && model_of_R->variable_of_region.size() == R.regions.size()) {
    // (The regions read through graphs change, and those whose lists did.)
    std::vector<uint8_t> changed(m.has_graph);
    for (uint32_t r = 0; r < R.regions.size(); ++r) {
      const int32_t x = model_of_R->variable_of_region[r];
      changed[r] |= x >= 0 && model_of_R->graph.domain[static_cast<uint32_t>(x)] != R.regions[r].states.size();
    }
    m.model = update_region_model(*model_of_R, dt, R, o, changed, limits.model, limits.dual.progress, &views);
  } else {
    m.model = region_model(dt, R, o, limits.model, limits.dual.progress, &views);
  }
  m.factors.resize(R.regions.size());
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    if (!graphs[r]) continue;
    RegionFactor& f = m.factors[r];
    f.graph = std::move(*graphs[r]);
    for (FillGraph::Arc& a : f.graph.arcs) a.cost *= sign;
    f.offset = -sign * terms.key(r, R.regions[r].states[0]).value;
    m.region_of_factor.push_back(r);
  }
  for (uint32_t x = 0; x < m.model.region_of_variable.size(); ++x) {
    const uint32_t r = m.model.region_of_variable[x], view = m.model.view_of_variable[x];
    if (!m.has_graph[r] || view == 0) continue;
    m.factors[r].scope.push_back(x);
    m.factors[r].item_of.push_back(view - 1);
  }
  return m;
}

}  // namespace

RegionDual region_dual(const Mesh& dt, const Regions& R, Objective o, const Candidates& cand, const RegionTerms& terms,
                       const Mesh* start, const RegionDualLimits& limits, const RegionModel* model_of_R) {
  RegionDual out;
  std::optional<GraphModel> built = graph_model(dt, R, o, cand, terms, limits, model_of_R);
  if (!built) {
    out.relaxed = static_cast<uint32_t>(R.incomplete);
    return out;
  }
  const RegionModel& model = built->model;
  const std::vector<RegionFactor>& factors = built->factors;
  const std::vector<uint32_t>& region_of_factor = built->region_of_factor;
  out.graphs = static_cast<uint32_t>(region_of_factor.size());
  out.graph_nodes.assign(R.regions.size(), 0);
  for (uint32_t r : region_of_factor) out.graph_nodes[r] = factors[r].graph.nodes;
  out.relaxed = built->relaxed;
  const StateGraph h = relaxation(model.graph);
  const std::optional<double> stop_at = start ? std::optional<double>(evaluate(o, *start)) : std::nullopt;
  const DualProof proof(h, limits.dual, stop_at, built->implicit());
  out.bound = proof.bound();
  if (!proof.applies()) return out;
  // Local search from the dual's decoded states and fills, and from `start`.
  const Descent descent(h, factors, region_of_factor);
  const std::vector<uint32_t> start_states = start ? listed_states(R, *start) : std::vector<uint32_t>(R.regions.size(), 0);
  auto found = [&](std::vector<uint32_t> state, std::vector<std::vector<Tri>> fills, uint32_t seed = 0) {
    descent.run(state, fills, seed);
    std::vector<Tri> tris;
    for (uint32_t r = 0; r < R.regions.size(); ++r) {
      const int32_t x = model.variable_of_region[r];
      const auto& states = R.regions[r].states;
      const auto& fill = built->has_graph[r] ? fills[r] : x < 0 ? states[0] : h.domain[static_cast<uint32_t>(x)] < 2 ? states[start_states[r]] : states[state[static_cast<uint32_t>(x)]];
      tris.insert(tris.end(), fill.begin(), fill.end());
    }
    const double v = evaluate(o, mesh_of(dt.coords, tris));
    out.found.push_back(std::move(tris));
    out.values.push_back(v);
    return v;
  };
  const Sense sense = info(o).sense;
  std::vector<std::vector<Tri>> fills(R.regions.size());
  std::vector<uint32_t> state = proof.decoded(), entries;
  for (size_t i = 0; i < region_of_factor.size(); ++i) {
    const RegionFactor& f = factors[region_of_factor[i]];
    f.best(proof.implicit_costs(i), fills[region_of_factor[i]], &entries);
    for (size_t j = 0; j < f.scope.size(); ++j) state[f.scope[j]] = entries[f.item_of[j]];
  }
  double best = found(state, fills);
  // Then the regions in other orders (each descent stops in a local optimum
  // of its own), until one meets the bound.
  for (uint32_t seed = 1; seed <= limits.restarts && better(sense, *out.bound, best); ++seed) {
    const double v = found(state, fills, seed);
    if (better(sense, v, best)) best = v;
  }
  if (!start) return out;
  // The start's states, and its fills' entries.
  for (uint32_t x = 0; x < h.domain.size(); ++x) state[x] = h.domain[x] < 2 ? 0 : start_states[model.region_of_variable[x]];
  for (uint32_t r : region_of_factor) {
    const RegionFactor& f = factors[r];
    fills[r] = R.regions[r].states[start_states[r]];
    for (const SignatureEntry& e : terms.key(r, fills[r]).signature) {
      const auto item = std::lower_bound(f.graph.items.begin(), f.graph.items.end(), RegionTerms::item_of(e));
      if (item == f.graph.items.end() || *item != RegionTerms::item_of(e)) return out;  // (not its part: no start)
      const auto& list = f.graph.entries[static_cast<size_t>(item - f.graph.items.begin())];
      const uint32_t id = static_cast<uint32_t>(std::find(list.begin(), list.end(), e) - list.begin());
      if (id == list.size()) return out;
      for (size_t j = 0; j < f.scope.size(); ++j)
        if (f.graph.items[f.item_of[j]] == *item) state[f.scope[j]] = id;
    }
  }
  const double v = found(state, fills);
  if (better(sense, v, best)) best = v;
  if (better(sense, *stop_at, best)) best = *stop_at;
  if (!out.relaxed) prove(dt, R, o, factors, region_of_factor, proof, best, limits, model_of_R, out);
  return out;
}

std::optional<double> region_threshold_bound(const Mesh& dt, const Regions& R, Objective o, const Candidates& cand,
                                             const RegionTerms& terms, double known, double incumbent,
                                             const RegionDualLimits& limits) {
  if (terms.terms().combine != Combine::Max || info(o).sense != Sense::Min || !(known < incumbent)) return std::nullopt;
  const std::optional<GraphModel> built = graph_model(dt, R, o, cand, terms, limits);
  if (!built) return std::nullopt;
  const StateGraph h = relaxation(built->model.graph);  // (terms it cannot see: 0, never above t)
  // The model's constant also holds the Delaunay fills' own terms of the
  // regions read through graphs (their implicit factors count those): the
  // terms fixed in every triangulation are known only when they exceed those.
  double own = 0;
  for (uint32_t r : built->region_of_factor) own = std::max(own, terms.key(r, R.regions[r].states[0]).value);
  const double fixed = h.constant > own ? h.constant : 0;
  // Every value a term can take in the model between known and incumbent.
  std::vector<double> values;
  auto add = [&](double v) {
    if (v >= known && v < incumbent) values.push_back(v);
  };
  for (const auto& u : h.unary)
    for (double v : u) add(v);
  for (const StateFactor& f : h.factors)
    for (double v : f.table) add(v);
  for (uint32_t r : built->region_of_factor)
    for (const FillGraph::Arc& a : built->factors[r].graph.arcs) add(a.cost);
  add(fixed);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  // Is every triangulation above t somewhere?
  auto refuted = [&](double t) {
    StateGraph c = h;
    c.combine = Combine::Sum;
    c.constant = fixed > t;
    for (auto& u : c.unary)
      for (double& v : u) v = v > t;
    for (StateFactor& f : c.factors)
      for (double& v : f.table) v = v > t;
    std::vector<RegionFactor> factors = built->factors;
    std::vector<const ImplicitFactor*> implicit;
    for (uint32_t r : built->region_of_factor) {
      for (FillGraph::Arc& a : factors[r].graph.arcs) a.cost = a.cost > t;
      factors[r].offset = 0;
      implicit.push_back(&factors[r]);
    }
    const DualProof proof(c, limits.dual, 2.0, implicit);  // (it may stop once the bound reaches 1)
    return proof.bound() && *proof.bound() >= 1;
  };
  // The largest value refuted (values below one refuted are refuted too).
  ptrdiff_t lo = -1, hi = static_cast<ptrdiff_t>(values.size());
  while (hi - lo > 1) {
    const ptrdiff_t mid = lo + (hi - lo) / 2;
    (refuted(values[static_cast<size_t>(mid)]) ? lo : hi) = mid;
  }
  if (lo < 0) return std::nullopt;
  return static_cast<size_t>(lo) + 1 < values.size() ? values[static_cast<size_t>(lo) + 1] : incumbent;
}

}  // namespace hodt
