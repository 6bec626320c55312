#include "exact/free_quads.hpp"

#include <stdexcept>

#include "exact/factor_models.hpp"

namespace hodt {

void solve_free_quads(const FirstOrder& fo, Objective o, const std::vector<uint8_t>& free, Choice& choice,
                      const DpLimits& limits) {
  // The fixed quads flipped into the base, the free ones its only quads. A flip
  // rewrites its own two triangles and the links into them, so every free quad
  // keeps its halfedge and corners, and the free quads keep their order.
  Mesh base = fo.base;
  std::vector<uint8_t> marked(base.halfedges.size(), 0);
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    if (free[q]) marked[fo.quads[q].edge] = 1;
    else if (choice[q]) flip_edge(base, fo.quads[q].edge);
  }
  const FirstOrder sub = first_order_of_marked(std::move(base), marked);
  // (Terms that no free quad changes are left out: only the choice is read.)
  const DpResult r = solve_exact(factor_model(sub, o, limits, OverBudget::Refuse, false), limits);
  uint32_t i = 0;
  for (uint32_t q = 0; q < fo.num_quads(); ++q)
    if (free[q]) choice[q] = r.choice[i++];
  if (i != sub.num_quads()) throw std::logic_error("free quads: the reduced structure lost a quad");
}

}  // namespace hodt
