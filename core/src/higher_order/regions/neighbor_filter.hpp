// Neighbour-set vertex terms at order k (ObjectiveTerms::drop_neighbors): the
// neighbours of a vertex that can still change its term, given the fixed edges
// that every order-k triangulation has. Fills and signatures (region_terms.hpp)
// keep only these, so fans that differ in nothing a term can see are one state.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/mesh.hpp"
#include "containers/words_memo.hpp"
#include "higher_order/regions/regions.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

class NeighborFilter {
 public:
  NeighborFilter(const Mesh& delaunay, const Regions& regions, const ObjectiveTerms& terms);
  bool active() const { return d_.drop_neighbors != nullptr; }
  // Drops from nb (sorted, v's neighbours so far) those that cannot change v's term.
  void reduce(uint32_t v, std::vector<uint32_t>& nb) const;
  // The ends of v's fixed and hull edges: its neighbours in every triangulation.
  const std::vector<uint32_t>& fixed(uint32_t v) const { return fixed_[v]; }

 private:
  const Mesh& dt_;
  const ObjectiveTerms& d_;
  std::vector<std::vector<uint32_t>> fixed_;
  mutable WordsMemo kept_;  // (v, nb) -> kept
  mutable std::vector<uint32_t> key_;
};

}  // namespace hodt
