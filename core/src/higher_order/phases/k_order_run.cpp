#include "higher_order/phases/k_order_run.hpp"

#include <algorithm>
#include <unordered_map>

#include "hodt/solve.hpp"
#include "engines/state_graph.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "objectives/pair_measures.hpp"

namespace hodt {

const Mesh& FirstOrderStart::get() {
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

KOrderRun::KOrderRun(const KOrderShared& s, uint32_t k, const SolveOptions& options, bool bounded,
                     const UsefulEdges* above)
    : shared(s),
      dt(s.fo.base),
      o(s.o),
      k(k),
      bounded(bounded),
      options(options),
      budgets(s.budgets),
      description(objective_terms(s.o, s.fo.base)),
      sense(info(s.o).sense),
      finding(in_phase(options.progress, Phase::FindingRegions)),
      exactly(in_phase(options.progress, Phase::SolvingExactly)),
      searching(in_phase(options.progress, Phase::Searching)),
      proving(in_phase(options.progress, Phase::ProvingBound)),
      above(above),
      answer(sense) {
  // Every triangulation of the points meets the global bound, so the answer's
  // starts there (a rung's proves nothing).
  if (bounded && description.global_bound)
    answer.tighten(description.global_bound(dt), "the bound that every triangulation of the points meets");
}

std::string KOrderRun::min_max_proof(double value) {
  // (A value tried in vain is not tried again: listing more states of the
  // regions not listed whole leaves the relaxation as it was.)
  if (!bounded || description.combine != Combine::Max || value == not_shown) return "";
  if (!better(sense, engine->terms.floor(), value)) return "its worst term is one that every k-OD triangulation has";
  if (none_below(relaxation(engine->model.graph), value, proving))
    return "no k-OD triangulation has every term below it (arc consistency over the regions' states)";
  not_shown = value;
  return "";
}

bool KOrderRun::prove_start() {
  const std::string why = min_max_proof(start_value);
  if (why.empty()) return false;
  answer.prove_with(std::move(start), start_value, "the " + start_name, why);
  return true;
}

// Each triangle of a k-OD triangulation lies in one region: the one beside any
// of its edges.
bool add_states_of(Regions& R, const Mesh& dt, const Mesh& m, std::vector<uint8_t>* changed) {
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

}  // namespace hodt
