// Neighbour-set vertex terms at order k (ObjectiveTerms::drop_neighbors): the
// neighbours of a vertex that can still change its term, given the fixed edges
// that every order-k triangulation has. Fills, signatures and the factor
// model's fan classes keep only these, so fans that differ in nothing a term
// can see are one state.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/objective_terms.hpp"
#include "hodt/regions.hpp"

namespace hodt {

class NeighborFilter {
 public:
  NeighborFilter(const Mesh& delaunay, const Regions& regions, const ObjectiveTerms& terms);
  bool active() const { return d_.drop_neighbors != nullptr; }
  // Drops from nb (sorted, v's neighbours so far) those that cannot change v's term.
  void reduce(uint32_t v, std::vector<uint32_t>& nb) const;
  // The ends of v's fixed and hull edges: neighbours in every triangulation
  // (kept when neighbour sets are reduced or counted).
  const std::vector<uint32_t>& fixed(uint32_t v) const { return fixed_[v]; }

 private:
  struct Hash {
    size_t operator()(const std::vector<uint32_t>& k) const {
      uint64_t h = 1469598103934665603ull;
      for (uint32_t x : k) h = (h ^ x) * 1099511628211ull;
      return static_cast<size_t>(h);
    }
  };
  const Mesh& dt_;
  const ObjectiveTerms& d_;
  std::vector<std::vector<uint32_t>> fixed_;
  mutable std::unordered_map<std::vector<uint32_t>, std::vector<uint32_t>, Hash> kept_;  // (v, nb) -> kept
  mutable std::vector<uint32_t> key_;
};

}  // namespace hodt
