// vertex_class (measures.hpp) for one centre over many neighbourhoods drawn
// from a few candidates: every choice of the quads around a vertex. The class
// asks whether some triangle of neighbours around the centre has it strictly
// below (above) its plane; which triangles of candidates do is found once, and
// a neighbourhood has such a witness when it holds all three of its corners.
// The same answers as vertex_class, for a bit mask per neighbourhood.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/measures.hpp"

namespace hodt {

class NeighbourhoodClasses {
 public:
  // Every neighbourhood holds the fixed candidates, and some of the optional
  // ones (at most 32). Past kMaxCandidates in all, each class is computed
  // directly.
  static constexpr uint32_t kMaxCandidates = 63;
  NeighbourhoodClasses(const double* centre, std::vector<const double*> fixed, std::vector<const double*> optional);
  // The class over the fixed candidates and the optional ones in mask (bit i:
  // optional candidate i).
  VertexClass of(uint32_t mask) const;

 private:
  const double* centre_;
  std::vector<const double*> candidates_;  // fixed, then optional
  uint32_t num_fixed_;
  bool direct_;
  // Each witness: the mask of its three corners among the candidates.
  std::vector<uint64_t> below_, above_;
};

}  // namespace hodt
