#include "higher_order/regions/neighbor_filter.hpp"

#include <algorithm>

namespace hodt {

NeighborFilter::NeighborFilter(const Mesh& dt, const Regions& R, const ObjectiveTerms& d) : dt_(dt), d_(d) {
  fixed_.resize(dt.num_vertices());
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e)
    if (dt.halfedges[e] < 0 || R.fixed[e]) {
      fixed_[dt.origin(e)].push_back(dt.target(e));
      fixed_[dt.target(e)].push_back(dt.origin(e));
    }
  for (auto& f : fixed_) {
    std::sort(f.begin(), f.end());
    f.erase(std::unique(f.begin(), f.end()), f.end());
  }
}

void NeighborFilter::reduce(uint32_t v, std::vector<uint32_t>& nb) const {
  if (!active() || nb.empty()) return;
  key_.assign(1, v);
  key_.insert(key_.end(), nb.begin(), nb.end());
  bool found = false;
  const std::span<const uint32_t> kept = kept_.find(key_, found);
  if (found) {
    nb.assign(kept.begin(), kept.end());
    return;
  }
  d_.drop_neighbors(dt_, v, fixed_[v], nb);
  kept_.insert(key_, nb);
}

}  // namespace hodt
