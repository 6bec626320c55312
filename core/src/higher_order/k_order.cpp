#include "higher_order/k_order.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <unordered_set>

#include "hodt/domain.hpp"
#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/solve.hpp"
#include "hodt/solve_options.hpp"
#include "engines/dual_bound.hpp"
#include "higher_order/bounds/region_dual.hpp"
#include "higher_order/bounds/star_bound.hpp"
#include "higher_order/bounds/star_decode.hpp"
#include "higher_order/bounds/view_bound.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/fills/fill_graph.hpp"
#include "higher_order/regions/glue_regions.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/regions/region_terms.hpp"
#include "higher_order/regions/regions.hpp"
#include "higher_order/search/fan_windows.hpp"
#include "higher_order/search/flip_search.hpp"
#include "higher_order/search/k_order_baker.hpp"
#include "objectives/pair_measures.hpp"

namespace hodt {

Mesh mesh_of(const Coords& coords, const std::vector<Tri>& triangles) {
  Mesh m;
  m.coords = coords;
  for (const Tri& t : triangles) m.triangles.insert(m.triangles.end(), t.begin(), t.end());
  canonicalize(m);
  return m;
}

bool enumerate_k_order(const Mesh& dt, uint32_t k, uint64_t max_nodes,
                       const std::function<void(const std::vector<Tri>&)>& visit, const Progress& progress) {
  const Candidates cand = k_order_candidates(dt, k, useful_edges(dt, k));
  std::vector<std::pair<uint32_t, uint32_t>> hull;
  for (size_t i = 0; i < dt.hull.size(); ++i) hull.push_back({dt.hull[i], dt.hull[(i + 1) % dt.hull.size()]});
  return enumerate_fills(dt, cand, hull, max_nodes, visit, progress);
}

namespace {

KOrderResult brute_force_k_order(const Mesh& dt, Objective o, uint32_t k, uint64_t max_nodes, const Progress& progress) {
  if (dt.num_vertices() > kKOrderBruteForceMaxPoints)
    throw LimitError("brute force at order " + std::to_string(k) + " enumerates every k-OD triangulation and refuses " +
                     std::to_string(dt.num_vertices()) + " points (at most " +
                     std::to_string(kKOrderBruteForceMaxPoints) + "); use --method exact or auto");
  KOrderResult r;
  const Sense sense = info(o).sense;
  bool have = false;
  std::vector<Tri> best;
  const bool complete = enumerate_k_order(dt, k, max_nodes, [&](const std::vector<Tri>& tris) {
    ++r.enumerated;
    const double v = evaluate(o, mesh_of(dt.coords, tris));
    if (!have || better(sense, v, r.value)) r.value = v, best = tris, have = true;
  }, progress);
  if (!complete || !have)
    throw LimitError("brute force at order " + std::to_string(k) + ": more than " + std::to_string(max_nodes) +
                     " search nodes; use --method exact or auto");
  r.triangulation = mesh_of(dt.coords, best);
  r.optimal = true;
  r.method = "brute-force";
  r.details = std::to_string(r.enumerated) + " k-OD triangulations enumerated";
  return r;
}

// Adds to each incomplete region the part of a k-OD triangulation that lies in it
// (each of its triangles lies in one region: the one beside any of its edges).
// Returns whether any was added; marks the regions it added to in `changed`
// (when given: one flag per region).
bool add_states_of(Regions& R, const Mesh& dt, const Mesh& m, std::vector<uint8_t>* changed = nullptr) {
  if (!R.incomplete) return false;
  // (Only the incomplete regions' corners: a triangle in a region has its corners there.)
  std::vector<uint8_t> corner(dt.num_vertices(), 0);
  for (const Region& region : R.regions)
    if (!region.complete)
      for (uint32_t t : region.delaunay_triangles)
        for (uint32_t i = 0; i < 3; ++i) corner[dt.triangles[3 * t + i]] = 1;
  std::unordered_map<uint64_t, uint32_t> delaunay_edge;  // directed edge -> halfedge
  for (uint32_t e = 0; e < dt.triangles.size(); ++e)
    if (corner[dt.origin(e)]) delaunay_edge[edge_key(dt.origin(e), dt.target(e))] = e;
  const std::vector<int32_t> start = vertex_halfedges(dt);
  std::vector<std::vector<Tri>> part(R.regions.size());
  for (uint32_t t = 0; t < m.num_triangles(); ++t) {
    Tri c = base_triangle(m, t);
    if (!corner[c[0]] || !corner[c[1]] || !corner[c[2]]) continue;
    const auto it = delaunay_edge.find(edge_key(c[0], c[1]));
    // A Delaunay edge: the Delaunay triangle on the same side. Else the segment's
    // first Delaunay triangle, which it splits (the region has it on both sides).
    const uint32_t h = it != delaunay_edge.end() ? it->second : crossed_edges(dt, start, c[0], c[1]).front();
    const uint32_t r = R.region_of_triangle[h / 3];
    if (R.regions[r].complete) continue;
    part[r].push_back(canonical_triangle(c));
  }
  bool added = false;
  for (size_t r = 0; r < R.regions.size(); ++r) {
    Region& region = R.regions[r];
    if (region.complete) continue;
    std::sort(part[r].begin(), part[r].end());
    if (std::find(region.states.begin(), region.states.end(), part[r]) == region.states.end()) {
      region.states.push_back(std::move(part[r]));
      added = true;
      if (changed) (*changed)[r] = 1;
    }
  }
  return added;
}

// The first order optimum, the heuristic's start at every order of the ladder:
// solved once.
struct FirstOrderStart {
  const FirstOrder& fo;
  Objective o;
  const SolveOptions& options;
  std::optional<Mesh> mesh;
  double value = 0;
  std::optional<Solution> solution;  // (method auto)
  const Mesh& get() {
    if (!mesh) {
      SolveOptions first = options;
      first.method = Method::Auto;
      first.order = 1;
      first.progress = hold_in_phase(options.progress, Phase::Searching);  // (the search's start)
      solution = solve(fo, o, first);
      mesh = triangulate(fo, solution->choice);
      value = evaluate(o, *mesh);
    }
    return *mesh;
  }
};

// When every region at order k is a quad or a triangle, the k-OD
// triangulations are the choices of a diagonal per quad: a singly flippable
// structure, which the first order solvers take as it is (their fast paths and
// proven bounds). The common case of DEM grids whose cells are not square, up
// to k = 3 or more. Not for brute force (which enumerates the instance).
// When the quads are the first order ones (every first order quad is one, so
// equal counts say so), the first order result is the answer (method auto:
// the ladder's, solved once). Within a domain only then: the first order
// paths read the domain on any quads (a triangle's being inside depends on its
// quad's diagonal alone, solve.cpp), but where they refuse they hand over to
// the region engine at order 1, whose regions are the first order quads.
std::optional<KOrderResult> solve_as_quads(const Mesh& dt, Objective o, const Regions& skeleton,
                                           const SolveOptions& options, FirstOrderStart& first_order) {
  if (options.method == Method::BruteForce) return std::nullopt;
  uint32_t quads_at_k = 0;
  for (const Region& region : skeleton.regions) {
    if (region.delaunay_triangles.size() > 2) return std::nullopt;
    quads_at_k += region.delaunay_triangles.size() == 2;
  }
  const bool same = quads_at_k == first_order.fo.num_quads();
  if (!same && has_domain(dt)) return std::nullopt;
  std::optional<FirstOrder> own;
  if (!same) {
    std::vector<uint8_t> marked(dt.halfedges.size(), 0);
    for (uint32_t e = 0; e < dt.halfedges.size(); ++e) marked[e] = !skeleton.fixed[e] && dt.halfedges[e] > static_cast<int32_t>(e);
    own = first_order_of_marked(dt, marked);
  }
  const FirstOrder& quads = same ? first_order.fo : *own;
  SolveOptions one = options;
  one.order = 1;
  const bool reuse = same && options.method == Method::Auto;
  if (reuse) first_order.get();
  const Solution s = reuse ? *first_order.solution : solve(quads, o, one);
  KOrderResult r;
  r.triangulation = triangulate(quads, s.choice);
  r.value = evaluate(o, r.triangulation);
  r.optimal = s.optimal;
  if (s.bound) r.bound = *s.bound;
  r.method = s.method;
  r.details = std::to_string(quads.num_quads()) + " regions with a choice, each a quad: a diagonal per quad, solved as at order 1" +
              (s.details.empty() ? std::string() : " (" + s.details + ")");
  return r;
}

// Gives the regions over the first budgets a second, larger DP pass (the
// largest first), kept only if then every region is whole; not when a region is
// over the size the first pass enumerates at all (at k >= 6 those have
// astronomically many signatures and would only cost time), nor when the first
// pass ran out of budget on one before it had placed 70 % of its triangles (its
// frontier still widening, it did not fit 25 times that budget either: DEMs at
// k = 4, 10,000 points, real and smooth, and 131k cells, every objective that
// failed had one between 41 and 64 %; those that fit, none under 76 %; the pass
// that fails costs as much as all the rest: 10,000 real DEM points, max-convex-
// vertices 9.7 -> 5.9 s, max-convex-edges 7.8 -> 4.2 s). Returns whether every
// region is listed whole.
bool list_whole(const Mesh& dt, Objective o, RegionEngine& engine, const Progress& progress) {
  Regions& R = engine.R;
  const bool listable = std::none_of(R.regions.begin(), R.regions.end(), [&](const Region& g) {
    return !g.complete && (g.delaunay_triangles.size() > engine.limits.max_region_triangles || g.swept < 0.7);
  });
  if (!R.incomplete || !listable) return !R.incomplete;
  Regions listed = R;
  std::vector<uint8_t> changed(R.regions.size(), 0);
  for (size_t r = 0; r < R.regions.size(); ++r) changed[r] = !R.regions[r].complete;
  RegionLimits wide = engine.limits;
  wide.only_incomplete = true;
  wide.max_states_per_region = 100'000;
  wide.max_states_per_region_dp = 500'000;
  wide.max_total_states = 1'500'000;
  enumerate_regions(dt, R, wide);
  if (R.incomplete) R = std::move(listed);
  else engine.model = update_region_model(std::move(engine.model), dt, R, o, changed, engine.model_limits, progress);
  return !R.incomplete;
}

// The region dual's sweeps. Strips side by side, as DEM grids give from k = 5,
// couple along whole boundaries and the ascent climbs slowly: a 20k-cell DEM's
// max-convex-edges bound is 34804 after 400 sweeps, 34391 after 1500, for 33872
// found.
constexpr uint32_t kDualSweeps = 1500;
// A ladder's rung from order 5 on wants the dual's descents (its start's
// quality), not its bound: a 40k-cell DEM crop at k = 6 found 19731 convex
// vertices either way, in 141 s instead of 173, and 68854 convex edges for 68861,
// in 147 s instead of 166 (without the dual: 19679 and 68854).
constexpr uint32_t kRungDualSweeps = 150;
constexpr uint32_t kMaxGlue = 2;
// The short reading before a ladder's lower order (10,000 DEM points at k = 4,
// max-convex-edges: proven after 150 sweeps, not after 50).
constexpr uint32_t kQuickSweeps = 150;

// Counts over regions not listed whole: the dual reads them through their fill
// graphs (region_dual.hpp); the best triangulation its descents found replaces
// r when better, and its proof makes r optimal. Returns the bound.
// glue: while a gap is left and every region not listed whole was read
// through its graph, those are glued in pairs (glue_regions.hpp) and read
// again, up to max_glue times: the bound tightens and the descent moves
// whole pairs. Each level is read in a second pairing too, none of the first's
// pairs (strips: shifted by one), whose descents leave other local optima.
// (The volcano at k = 4, 86 strips each of one column of cells:
// max-convex-edges 6923 with bound 6940 unglued; glued twice, 6939 proven.
// A 20k-cell DEM at k = 5: 33881 with bound 34391; glued once, 34051 with
// bound 34227.) unglued (when given): with max_glue 0, the first reading, kept
// when a gap is left that glue might close; given back with it, the levels
// start from it instead of reading R again.
std::optional<double> bound_by_fill_graphs(const Mesh& dt, Objective o, RegionEngine& engine, KOrderResult& r,
                                           std::string& how, const Progress& progress, uint32_t max_glue = 0,
                                           uint32_t max_sweeps = kDualSweeps,
                                           std::optional<RegionDual>* unglued = nullptr) {
  const Sense sense = info(o).sense;
  RegionDualLimits limits;
  limits.dual.progress = limits.dp.progress = progress;
  limits.model = engine.model_limits;
  limits.dp.max_table = 1 << 24;
  limits.dual.max_sweeps = max_sweeps;
  std::optional<double> bound;
  // One reading of R: its descents' best replaces r when better, its bound
  // tightens `bound`; true when it proved r optimal.
  auto read = [&](Regions& R, const RegionTerms& terms, const std::string& glued, RegionDual& d) {
    add_states_of(R, dt, r.triangulation);
    // (The engine's model is of its regions, but for those not listed whole.)
    d = region_dual(dt, R, o, engine.cand, terms, &r.triangulation, limits, &R == &engine.R ? &engine.model : nullptr);
    const std::string what = std::to_string(d.graphs) + " graphs" + glued;
    size_t best = d.found.size();
    for (size_t i = 0; i < d.found.size(); ++i)
      if (better(sense, d.values[i], best < d.found.size() ? d.values[best] : r.value)) best = i;
    if (best < d.found.size()) {
      r.triangulation = mesh_of(dt.coords, d.found[best]), r.value = d.values[best];
      how += ", then descent over the regions' fill graphs from the dual (" + what + ")";
    }
    if (d.bound) bound = bound ? tighter(sense, *bound, *d.bound) : d.bound;
    if (!d.proven) return false;
    if (d.optimum) {
      r.value = evaluate(o, *d.optimum);
      r.triangulation = std::move(*d.optimum);
      if (r.value != d.optimum_value) throw std::logic_error("order k: the fill graphs' model value differs from the triangulation's");
    }
    r.optimal = true;
    r.bound.reset();
    r.method = "exact";
    r.details = region_summary(engine.R) + "; the dual read " + what + ", kept " + std::to_string(d.listed) +
                " of their fills, and the dual proof over those proved " +
                (d.optimum ? std::string("its optimum") : "the heuristic's result (" + how + ")") + " optimal";
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
    // about twice n_a n_b / max(l_a, l_b) (strips of a DEM and of the volcano,
    // pairs and pairs of pairs): pairs whose estimate, doubled, is over the
    // graphs' budget are not glued, nor regions of unlike lengths (a short
    // region beside a long one widens the sweep's frontier where they overlap
    // and gains little: on a DEM at k = 5 they did not fit).
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
    // terms' states decide the graphs' size too: min-mixed-vertices' strips at
    // k = 5 on a DEM do not fit in pairs where max-convex-edges' do).
    // And the level must fit the graphs' total budget (else its last graphs
    // would be left out, and the bound with them): a 131k-cell DEM at k = 5
    // (358 strips) is not glued, a 20k-cell crop of it (54) is.
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
  auto gap = [&] { return bound && better(sense, *bound, r.value); };
  RegionDual d;
  if (unglued && *unglued) {
    d = std::move(**unglued), bound = d.bound;
    unglued->reset();
  } else if (read(engine.R, engine.terms, "", d)) {
    return bound;
  }
  const Regions* parent = &engine.R;
  std::unique_ptr<Level> level;
  // (Each level costs a dual as large as the first: on hundreds of strips, a
  // 131k-cell DEM at k = 5 has 358, that is minutes per level, for gaps already
  // under 2 %.)
  constexpr uint32_t kMaxGlued = 128;
  auto gluable = [&] { return gap() && !d.relaxed && d.graphs >= 2 && d.graphs <= kMaxGlued; };
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

// Counts: the dual bound (dual_bound.hpp), once the cheaper bounds left a gap.
// Over a whole model it gives local search one more start, then proves the
// best triangulation found optimal (r.optimal, r.method "exact") or finds the
// optimum, by pruning and the DP over what is left. It needs every region
// listed whole (list_whole, tried first of all); else those not listed whole are read through
// their fill graphs, unglued (`unglued`: that reading, when gluing might tighten
// its bound). Returns the bound (nothing if it does not apply).
std::optional<double> prove_by_dual(const Mesh& dt, Objective o, RegionEngine& engine, KOrderResult& r, std::string& how,
                                    const std::string& refused, const Progress& progress,
                                    std::optional<RegionDual>& unglued) {
  Regions& R = engine.R;
  RegionModel& model = engine.model;
  const Sense sense = info(o).sense;
  DualLimits dual;
  dual.progress = progress;
  dual.max_rounds = 2;
  if (R.incomplete) return bound_by_fill_graphs(dt, o, engine, r, how, progress, 0, kDualSweeps, &unglued);
  StateDpLimits dl;
  dl.progress = progress;
  // Two clusterings in turn: the ascent stops at a fixed point of its own in
  // each, and a proof turns on the bound passing an integer (the pruning keeps
  // every state within one unit of it), so either may prove what the other
  // cannot; the second runs only if the first did not. The larger clusters
  // (the tighter relaxation) first: a 10,000-point DEM sample at k = 4,
  // max-convex-edges, proven by them alone, 6.3 -> 4.9 s.
  std::optional<double> bound;
  for (const double clusters : {4096.0, 1024.0}) {
    dual.cluster_entries = clusters;
    const DualProof proof(model.graph, dual, r.value);
    if (!proof.applies()) return bound;
    bound = bound ? tighter(sense, *bound, *proof.bound()) : proof.bound();
    StateDpLimits window = dl;
    window.max_table = 1 << 16;
    const std::vector<uint32_t> x =
        improve_by_windows(model.graph, improve_states(model.graph, proof.decoded(), progress), window, 24);
    Mesh m = R.triangulation(dt, model.region_states(x));
    const double v = evaluate(o, m);
    if (better(sense, v, r.value)) r.triangulation = std::move(m), r.value = v, how += ", then local search from the dual";
    // (What is left after pruning is far smaller: its DP may use a larger table.)
    StateDpLimits pruned = dl;
    pruned.max_table = 1 << 24;
    const DualProof::Proof p = proof.prove(r.value, pruned);
    if (!p.proven) continue;
    if (p.better) {
      r.triangulation = R.triangulation(dt, model.region_states(*p.better));
      r.value = evaluate(o, r.triangulation);
      if (r.value != p.better_value) throw std::logic_error("order k: the model's value differs from the triangulation's");
    }
    r.optimal = true;
    r.bound.reset();
    r.method = "exact";
    r.details = region_summary(R) + "; the dual bound (clusters of " + std::to_string(static_cast<int>(clusters)) +
                " entries) kept " + std::to_string(p.kept_states) + " of " + std::to_string(p.states) +
                " states and the DP over them proved " +
                (p.better ? std::string("its optimum") : "the heuristic's result (" + how + ")") +
                " optimal (the DP alone refused: " + refused + ")";
    break;
  }
  return bound;
}

// The bound from the vertices' stars (star_bound.hpp), tighter than `bound`
// or `bound` itself; the fans its multipliers favour, made to agree
// (star_decode.hpp), then flipped: where the relaxation is nearly tight, far
// past what flips and descents reach (the volcano at k = 8, max-convex-edges:
// 6984 before, 8020 so, for a bound of 8047). Sweeps four ways, then repairs of
// the best at hand while they improve it; then windows of 25 vertices, each at
// its best with the rest kept (fan_windows.hpp; the volcano at k = 4,
// min-mixed-vertices: 77 -> 76, the bound, in 0.5 s), while they improve it,
// then larger ones.
// value_side: the gap is more likely the value's (the regions' views moved the
// bound): two passes of windows come first, and the stars only if a gap is
// left (the 131k-cell DEM at k = 4, min-mixed-vertices: the views' bound is the
// optimum, the stars' is lower, and the windows reach it from the best at hand:
// 86 -> 63 s). The stars' best reading is then a second start when it does not
// beat the best at hand (windows from it can reach what they do not from there:
// with the windows first on the smooth DEM sample at k = 4, the best at hand
// stopped at 1222, and from the stars' reading, 1223, they reached 1221, the optimum).
// What improves r replaces it.
double by_stars(const Mesh& dt, Objective o, uint32_t k, const Candidates& cand, KOrderResult& r, double bound,
                std::string& how, const Progress& progress, VertexTermMemo* memo, bool value_side) {
  const Sense sense = info(o).sense;
  struct Start {
    Mesh triangulation;
    double value;
  };
  auto flipped = [&](const std::vector<Tri>& tris) {
    Mesh m = mesh_of(dt.coords, tris);
    improve_by_flips(m, dt, k, o, progress, memo);
    const double v = evaluate(o, m);
    return Start{std::move(m), v};
  };
  Start best{std::move(r.triangulation), r.value};
  std::optional<Start> second;
  bool decoded = false, windowed = false;
  auto adopt = [&](Start s) {
    if (better(sense, s.value, best.value)) {
      best = std::move(s), decoded = true;
      return true;
    }
    if (value_side && (!second || better(sense, s.value, second->value))) second = std::move(s);
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
  // most `passes` passes (and 16 in all), each with its tiles placed anew (a
  // move across one pass's tile borders may lie inside the next's: a 100 x 100
  // DEM crop at k = 8, min-mixed-vertices, 244 -> 243 for a bound of 240); true
  // if it improved s.
  WindowLimits windows;
  windows.progress = progress;
  uint32_t placement = 0;  // (the passes so far)
  auto descend = [&](Start& s, uint32_t size, uint32_t passes) {
    windows.per_window = size;
    bool improved = false;
    for (uint32_t pass = 0; pass < passes && placement < 16 && better(sense, bound, s.value); ++pass) {
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
  if (value_side) windowed = descend(best, 25, 2);
  if (better(sense, bound, best.value)) {
    StarBoundLimits stars;
    stars.progress = progress;
    stars.decode = true;
    stars.known_bound = bound;
    // (Tiles of many, as the 131k-cell DEM at k = 8 has, decode one by one, the
    // rest held at the best at hand.)
    stars.start = &best.triangulation;
    stars.decoded_tile = decode;
    const auto b = star_bound(dt, o, cand, best.value, stars);
    if (b && better(sense, bound, b->bound)) {
      bound = b->bound;
      how += ", bound from the vertices' stars";
    }
    if (b && b->decoder) decode(*b->decoder);
    if (value_side && second && descend(*second, 25, 2) && better(sense, second->value, best.value))
      best = std::move(*second), decoded = windowed = true;
    // Then windows of 25 vertices while they improve it, then of 40, 64 and 102:
    // a move that no window of one size holds may fit one of the next (10,000
    // DEM points at k = 4, min-mixed-vertices, 1458 -> 1457, the bound; the
    // volcano at k = 8, 13 -> 12, the bound).
    for (const uint32_t size : {25u, 40u, 64u, 102u}) windowed = descend(best, size, 16) || windowed;
  }
  r.triangulation = std::move(best.triangulation), r.value = best.value;
  if (decoded) how += ", then a triangulation read off the stars";
  if (windowed) how += ", then descent by windows of fans";
  return bound;
}

// bounded: whether a heuristic answer needs its bound (the ladder's lower
// orders serve only as starts).
KOrderResult solve_regions(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options, const RegionLimits& budgets,
                           FirstOrderStart& first_order, VertexTermMemo* memo, bool bounded = true,
                           const UsefulEdges* above = nullptr) {
  const Mesh& dt = fo.base;
  if (options.method == Method::BruteForce) {
    return brute_force_k_order(dt, o, k, budgets.max_nodes_per_region, in_phase(options.progress, Phase::SolvingExactly));
  }
  // The phases of this order's steps (progress.hpp).
  const Progress finding = in_phase(options.progress, Phase::FindingRegions);
  const Progress exactly = in_phase(options.progress, Phase::SolvingExactly);
  const Progress searching = in_phase(options.progress, Phase::Searching);
  const Progress proving = in_phase(options.progress, Phase::ProvingBound);
  const ObjectiveTerms& description = objective_terms(o, dt);
  const Sense sense = info(o).sense;
  const double global = description.global_bound ? description.global_bound(dt) : sense == Sense::Min ? -INFINITY : INFINITY;
  if (bounded && k >= 2 && description.global_bound) first_order.get();
  if (bounded && k >= 2 && description.global_bound && !better(sense, global, first_order.value)) {
    // The first order optimum meets a bound that every triangulation meets.
    KOrderResult r;
    r.triangulation = *first_order.mesh;
    r.value = first_order.value;
    r.optimal = true;
    r.method = "exact";
    r.details = "the first order optimum meets the bound that every triangulation of the points meets";
    return r;
  }
  // (The ladder's rungs read their useful edges from the top order's.)
  const UsefulEdges by_order = above ? UsefulEdges{} : useful_edges_by_order(dt, k, finding);
  const UsefulEdges& orders = above ? *above : by_order;
  std::vector<std::pair<uint32_t, uint32_t>> useful = orders.at(k);
  Regions skeleton = k_order_skeleton(dt, k, useful, finding);
  if (k >= 2)  // (order 1 stays on the general engine: solve() takes the first order paths itself)
    if (auto quads = solve_as_quads(dt, o, skeleton, options, first_order)) return *quads;
  // The ladder's rung below: every j-OD triangulation (j < k) is k-OD, so the
  // result at order j gives each region one more listed triangulation and a
  // start no worse. Up to order 8 the rung is k - 1 (order 4 for k = 5 to 8 gave
  // the 131k DEM fewer convex vertices at k = 6 than at k = 5); above, half of k.
  // (A rung stops before the stars' bound and what follows it, so an answer can
  // still trail the lower order's own.) From order 5 on (where the exact engine
  // rarely answers on large inputs) it is solved before this order's structures
  // are built: one order's regions in memory at a time; below, only if the
  // exact engine does not answer.
  std::optional<KOrderResult> lower;
  auto solve_lower = [&] {
    if (lower || k < 3) return;
    SolveOptions lower_options = options;
    lower_options.method = Method::Auto;
    lower_options.progress = hold_in_phase(options.progress, Phase::Searching);  // (a start for this order's search)
    lower = solve_regions(fo, o, k <= 8 ? k - 1 : k / 2, lower_options, budgets, first_order, memo, false, &orders);
  };
  if (k >= 5) solve_lower();
  const KOrderStructure structure(dt, k, std::move(useful), finding);
  RegionEngine engine(dt, o, structure, std::move(skeleton), budgets, finding, memo);
  Regions& R = engine.R;
  const Candidates& cand = engine.cand;
  const RegionTerms& terms = engine.terms;
  RegionModel& model = engine.model;
  KOrderResult r;
  std::string refused = engine.exact_refusal().value_or("");
  // Counts may still be proven (by the dual bound, below): the regions over the
  // first budgets are listed whole first, when they look listable (list_whole),
  // and the exact engine may then answer alone, before the ladder's lower order
  // and the search it starts (10,000 real DEM points at k = 3: max-convex-vertices
  // 2.5 -> 1.7 s, min-mixed-vertices 3.1 -> 2.0 s; the 131k-cell DEM at k = 4,
  // max-convex-edges 21 -> 8.5 s).
  const bool counts = !model.graph.relaxed_terms && integral_sum(model.graph);
  const bool provable = bounded && counts;
  if (provable && R.incomplete && list_whole(dt, o, engine, finding))
    refused = engine.exact_refusal().value_or("");
  if (refused.empty() && options.method != Method::Approx) {
    uint32_t width = 0;
    if (auto x = engine.exact(exactly, refused, &width)) {
      r.triangulation = R.triangulation(dt, *x);
      r.value = evaluate(o, r.triangulation);
      r.optimal = true;
      r.method = "exact";
      r.details = region_summary(R) + "; tree decomposition of width " + std::to_string(width);
      return r;
    }
  }
  if (options.method == Method::Exact && !provable) throw LimitError("exact at order " + std::to_string(k) + ": " + refused);
  // Otherwise: the best triangulation over the triangulations each region has
  // listed (the first order optimum's among them, so never worse than it), by the
  // same DP when its tables fit, else by local search; the bound is the
  // relaxation's optimum.
  // (At order 1 the engine is the first order solver, within a domain: Delaunay starts.)
  Mesh start = k == 1 ? dt : first_order.get();
  double start_value = k == 1 ? evaluate(o, dt) : first_order.value;
  std::string start_name = k == 1 ? "Delaunay triangulation" : "first order optimum";
  // Min-max: why `value` is optimal, when the terms' floor (the largest term no
  // region can change: RegionTerms::floor) or arc consistency over the model's
  // relaxation (none_below) shows it; empty when neither does. Tried on the start
  // before any search over the regions, and on the search's answer before the
  // flips and the bound's threshold search (a 131k-cell DEM at k = 4:
  // minmax-edge-enclosing-circle 38 -> 8 s, the first order optimum meets the
  // floor; minmax-vertex-normal-angle 31 -> 10 s, arc consistency). A value
  // tried in vain is not tried again (listing more states of the regions not
  // listed whole leaves the relaxation as it was).
  double not_shown = NAN;
  auto min_max_proof = [&](double value) -> std::string {
    if (!bounded || description.combine != TermCombine::Max || value == not_shown) return "";
    if (!better(sense, terms.floor(), value)) return "its worst term is one that every k-OD triangulation has";
    if (none_below(relaxation(model.graph), value, proving))
      return "no k-OD triangulation has every term below it (arc consistency over the regions' states)";
    not_shown = value;
    return "";
  };
  auto start_proven = [&] {
    const std::string why = min_max_proof(start_value);
    if (why.empty()) return false;
    r.triangulation = std::move(start);
    r.value = start_value;
    r.optimal = true;
    r.method = "exact";
    r.details = region_summary(R) + "; the " + start_name + ": " + why + " (exact refused: " + refused + ")";
    return true;
  };
  if (start_proven()) return r;
  // r: the best combination of the regions' listed triangulations, or the start
  // when better (relaxed terms can mislead the search); returns how it was found.
  auto take_listed = [&](const ListedBest& listed) {
    r.triangulation = R.triangulation(dt, listed.regions);
    r.value = evaluate(o, r.triangulation);
    if (better(sense, start_value, r.value)) r.triangulation = start, r.value = start_value;
    return listed.how;
  };
  std::vector<uint8_t> changed(R.regions.size(), 0);
  bool added = add_states_of(R, dt, start, &changed);
  // Counts up to order 4 with regions not listed whole: a short reading of their
  // fill graphs from the best listed combination, before the ladder's lower
  // order, which can cost as much as this order's engine. It proves most real
  // terrains (10,000 DEM points at k = 4, max-convex-vertices, 4.3 -> 2.6 s in
  // the benchmark; the 131k-cell DEM, 17 s either way) and costs about a second
  // where it does not (a smooth DEM sample, the volcano; min-mixed-vertices,
  // which the stars prove, if anything). Proof or nothing: else the regions are left
  // as they were (what its descents find can be a worse start for the rest: on
  // the smooth sample, max-convex-vertices, 4711 for a bound of 4712 led the rest
  // to a bound in 21 s, the rung's start to the proof in 4).
  if (provable && k < 5 && R.incomplete && options.method != Method::Approx) {
    if (added) model = update_region_model(std::move(model), dt, R, o, changed, engine.model_limits, searching);
    changed.assign(R.regions.size(), 0), added = false;
    std::vector<size_t> counts(R.regions.size());
    for (size_t i = 0; i < R.regions.size(); ++i) counts[i] = R.regions[i].states.size();
    std::string how = take_listed(engine.best_listed(listed_states(R, start), searching));
    bound_by_fill_graphs(dt, o, engine, r, how, proving, 0, kQuickSweeps);
    if (r.optimal) return r;
    for (size_t i = 0; i < R.regions.size(); ++i) R.regions[i].states.resize(counts[i]);
  }
  solve_lower();
  if (lower) {
    added = add_states_of(R, dt, lower->triangulation, &changed) || added;
    if (better(sense, lower->value, start_value))
      start = std::move(lower->triangulation), start_value = lower->value, start_name = "answer at order " + std::to_string(k <= 8 ? k - 1 : k / 2);
    if (start_proven()) return r;
  }
  if (added) model = update_region_model(std::move(model), dt, R, o, changed, engine.model_limits, searching);
  const ListedBest listed = engine.best_listed(listed_states(R, start), searching);
  if (bounded && listed.bound_only && !R.incomplete && !model.graph.relaxed_terms &&
      !better(sense, listed.listed_value, start_value)) {
    // The model is the whole problem, so its mini-bucket value bounds the
    // optimum, and the start already meets it.
    r.triangulation = std::move(start);
    r.value = start_value;
    r.optimal = true;
    r.method = "heuristic";
    r.details = region_summary(R) + "; the start meets the mini-bucket bound (exact refused: " + refused + ")";
    return r;
  }
  std::string how = take_listed(listed);
  const std::string proof = min_max_proof(r.value);
  const bool refuted = !proof.empty();
  if (refuted) how += "; " + proof;
  // Asked for the approximation scheme: Baker's shifting (the paper's Theorem
  // 10), bands of Delaunay triangles kept every lambda layers cut the regions too
  // large for the engine (slower: lambda runs of it).
  if (!refuted && bounded && k >= 2 && options.method == Method::Approx) {
    const KOrderBaker b = k_order_baker(dt, o, structure, k, options.epsilon, budgets.max_nodes_per_region, in_phase(options.progress, Phase::Approximating));
    if (b.triangulation && better(sense, b.value, r.value))
      r.triangulation = std::move(*b.triangulation), r.value = b.value, how = b.summary();
    else if (b.shifts)
      how += " (" + b.summary() + ": no better)";
  }
  // Then k-OD flips that improve the terms around them (they reach into the
  // regions too large to list).
  Mesh flipped = r.triangulation;
  if (!refuted && improve_by_flips(flipped, dt, k, o, searching, memo)) {
    const double v = evaluate(o, flipped);
    if (better(sense, v, r.value)) r.triangulation = std::move(flipped), r.value = v, how += ", then k-OD flips";
  }
  r.method = "heuristic";
  if (!bounded) {  // (a start for a higher order: nothing proven, but the regions' fill graphs may improve it)
    if (counts && R.incomplete)
      bound_by_fill_graphs(dt, o, engine, r, how, searching, 0, k >= 5 ? kRungDualSweeps : kDualSweeps);
    r.optimal = false;
    return r;
  }
  StateDpLimits dl;
  dl.progress = proving;
  // The bound: the model's relaxation, or the tighter one that reads the regions
  // too large to list through their views; when those views agree, a
  // triangulation that meets it.
  // (Counts, unless approx is asked, read it only if the dual's proof, which
  // needs no other bound, did not come: a 10k-point DEM sample at k = 4,
  // max-convex-edges, 1.1 s.)
  auto relaxed = [&] { return tighter(sense, relaxation_bound(model.graph, dl), global); };
  const bool dual_first = provable && options.method != Method::Approx;
  std::optional<RegionDual> unglued;  // (the fill graphs' first reading, when glue might tighten it)
  double bound = refuted ? r.value : dual_first ? global : relaxed();
  if (description.combine == TermCombine::Max) bound = tighter(sense, bound, terms.floor());
  // Counts: the dual before the views (it proves most instances on its own: a
  // 131k-cell DEM at k = 4, max-convex-vertices, where the views cost twice the
  // dual and proved nothing).
  if (provable && better(sense, bound, r.value)) {
    if (const std::optional<double> d = prove_by_dual(dt, o, engine, r, how, refused, proving, unglued)) {
      if (r.optimal) return r;
      bound = tighter(sense, bound, *d);
    }
    if (dual_first) bound = tighter(sense, bound, relaxed());
  }
  ViewBoundLimits vl;
  vl.views.progress = vl.dp.progress = proving;
  vl.model = engine.model_limits;
  const bool met = !better(sense, bound, r.value);
  bool views_moved = false;  // (the regions' views tightened the bound)
  if (const auto vb = met ? std::nullopt : view_bound(dt, R, o, cand, terms, engine.limits.max_region_triangles, r.value, bound, vl)) {
    views_moved = better(sense, bound, vb->bound);
    bound = tighter(sense, bound, vb->bound);
    if (vb->realised && !better(sense, r.value, vb->bound)) {
      r.triangulation = *vb->realised;
      r.value = vb->bound;  // (its value, evaluated)
      how += ", then the regions' views (" + std::to_string(vb->split_regions) + " regions, " +
             std::to_string(vb->rounds) + " rounds)";
    }
  }
  // Min-max over regions not listed whole: thresholds refuted by the dual over their fill graphs.
  if (description.combine == TermCombine::Max && R.incomplete && better(sense, bound, r.value)) {
    RegionDualLimits limits;
    limits.dual.progress = proving;
    limits.dual.max_sweeps = 100;
    limits.model = engine.model_limits;
    if (const auto t = region_threshold_bound(dt, R, o, cand, terms, bound, r.value, limits)) {
      bound = tighter(sense, bound, *t);
      how += ", bound by thresholds over the regions' fill graphs";
    }
  }
  // Min-max: every vertex takes one of its fans, each fan's worst term bounds
  // (the volcano at k = 8, where one region holds everything: vertex normal angle
  // bound 0 before).
  if (description.combine == TermCombine::Max && better(sense, bound, r.value)) {
    StarBoundLimits stars;
    stars.progress = proving;
    if (const auto f = star_floor(dt, o, cand, stars); f && better(sense, bound, *f)) {
      bound = *f;
      how += ", bound from the vertices' fans";
    }
  }
  // Counts and lengths: the bound from the vertices' stars, which lists no
  // region (one region of thousands of triangles, as from k = 6 on the volcano, too).
  if (description.combine == TermCombine::Sum && better(sense, bound, r.value))
    bound = by_stars(dt, o, k, cand, r, bound, how, proving, memo, views_moved);
  // The regions' fill graphs glued in pairs only now, where the stars left a gap
  // (10,000 DEM points at k = 4, min-mixed-vertices, 30 -> 25 s, and the 131k-cell
  // DEM, 78 -> 70 s: the stars prove what two levels of glue did not).
  if (unglued && better(sense, bound, r.value)) {
    if (const std::optional<double> d = bound_by_fill_graphs(dt, o, engine, r, how, proving, kMaxGlue, kDualSweeps, &unglued)) {
      if (r.optimal) return r;
      bound = tighter(sense, bound, *d);
    }
  }
  r.bound = sense == Sense::Min ? std::min(bound, r.value) : std::max(bound, r.value);
  r.optimal = *r.bound == r.value;
  if (options.method == Method::Exact && !r.optimal)
    throw LimitError("exact at order " + std::to_string(k) + ": " + refused + "; the dual bound left a gap");
  if (r.optimal) r.bound.reset();
  r.details = region_summary(R) + "; " + how + " (" +
              (refused.empty() ? std::string("approx asked") : "exact refused: " + refused) + ")";
  return r;
}

}  // namespace

KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options,
                           const RegionLimits& budgets) {
  if (!fo.is_delaunay) throw InputError("higher order needs the Delaunay triangulation: not for user triangulations");
  FirstOrderStart first_order{fo, o, options, {}, 0, {}};
  VertexTermMemo memo;  // (the ladder's orders meet the same stars too)
  KOrderResult r = solve_regions(fo, o, k, options, budgets, first_order, &memo);
  r.delaunay_value = evaluate(o, fo.base);
  return r;
}

KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options, uint64_t max_nodes) {
  RegionLimits budgets;
  budgets.max_nodes_per_region = max_nodes;
  return solve_k_order(fo, o, k, options, budgets);
}

Solution k_order_solution(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options) {
  SolveOptions checked = options;
  checked.order = k;
  check_options(checked);
  const auto t0 = std::chrono::steady_clock::now();
  KOrderResult r = solve_k_order(fo, o, k, options);
  if (!is_k_order(r.triangulation, fo.base, k, in_phase(options.progress, Phase::Measuring))) throw std::logic_error("order k result is not k-OD");
  Solution s;
  s.objective = o;
  s.method = r.method;
  s.order = k;
  s.value = r.value;
  s.delaunay_value = r.delaunay_value;
  s.optimal = r.optimal;
  s.bound = r.bound;
  s.details = r.details;
  // Edges of the result that are not Delaunay edges.
  std::unordered_set<uint64_t> delaunay_edges;
  const Mesh& dt = fo.base;
  for (uint32_t e = 0; e < dt.triangles.size(); ++e)
    delaunay_edges.insert(edge_key(std::min(dt.origin(e), dt.target(e)), std::max(dt.origin(e), dt.target(e))));
  const Mesh& m = r.triangulation;
  for (uint32_t e = 0; e < m.triangles.size(); ++e)
    if (m.halfedges[e] < static_cast<int32_t>(e))
      s.non_delaunay_edges += !delaunay_edges.count(edge_key(std::min(m.origin(e), m.target(e)), std::max(m.origin(e), m.target(e))));
  s.critical = critical_pair(o, m, {}, r.value);  // (its value known: pairs below it cut short)
  s.mesh = std::move(r.triangulation);
  s.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace hodt
