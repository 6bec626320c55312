#include "hodt/domain.hpp"
#include "higher_order/phases/phases.hpp"

namespace hodt {

void meet_global_bound(KOrderRun& run) {
  const Mesh& first = run.shared.first_order.get();
  // (The answer's bound starts at the global bound: the offer is proven when it meets it.)
  if (!better(run.sense, run.bound(), run.shared.first_order.value))
    run.answer.offer(first, run.shared.first_order.value, "the first order optimum");
}

// The common case of DEM grids whose cells are not square, up to k = 3 or
// more. When the quads are the first order ones (every first order quad is
// one, so equal counts say so), the first order result is the answer (method
// auto: the ladder's start, solved once). Within a domain only then: the first
// order paths read the domain on any quads (a triangle's being inside depends
// on its quad's diagonal alone), but where they refuse they hand over to the
// region engine at order 1, whose regions are the first order quads.
void solve_as_quads(KOrderRun& run) {
  const Mesh& dt = run.dt;
  uint32_t quads_at_k = 0;
  for (const Region& region : run.skeleton.regions) {
    if (region.delaunay_triangles.size() > 2) return;
    quads_at_k += region.delaunay_triangles.size() == 2;
  }
  FirstOrderStart& first_order = run.shared.first_order;
  const bool same = quads_at_k == first_order.fo.num_quads();
  if (!same && has_domain(dt)) return;
  std::optional<FirstOrder> own;
  if (!same) {
    std::vector<uint8_t> marked(dt.halfedges.size(), 0);
    for (uint32_t e = 0; e < dt.halfedges.size(); ++e) marked[e] = !run.skeleton.fixed[e] && dt.halfedges[e] > static_cast<int32_t>(e);
    own = first_order_of_marked(dt, marked);
  }
  const FirstOrder& quads = same ? first_order.fo : *own;
  SolveOptions one = run.options;
  one.order = 1;
  const bool reuse = same && run.options.method == Method::Auto;
  if (reuse) first_order.get();
  const Solution s = reuse ? *first_order.solution : solve(quads, run.o, one);
  Mesh m = triangulate(quads, s.choice);
  const double v = evaluate(run.o, m);
  run.answer.offer(std::move(m), v, "a diagonal per quad");
  if (s.optimal) run.answer.prove("the first order solver's");
  else if (s.bound) run.answer.tighten(*s.bound, "the first order solver's");
  // The first order solver's answer is final as it is, with its method and details.
  run.method = s.method;
  run.details = std::to_string(quads.num_quads()) +
                " regions with a choice, each a quad: a diagonal per quad, solved as at order 1" +
                (s.details.empty() ? std::string() : " (" + s.details + ")");
}

}  // namespace hodt
