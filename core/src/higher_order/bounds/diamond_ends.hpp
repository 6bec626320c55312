// The diamonds of a tile's fans (star_bound.hpp): an edge with the triangles on
// either side of it (one at a hull edge). In v's fan a diamond is a neighbour u
// with the neighbours before and after it (FanSide); u's fan holds the same
// diamond seen from the other end (mirrored), or neither fan does. Each vertex's
// view of a diamond is an end, numbered per tile. A fan holds the end at u at
// the node of the triangle after u, but at its leaf for the leaf's own
// neighbour (round an interior vertex the first, whose triangle after is the
// fan's first; at a hull vertex the last, with none after).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "higher_order/bounds/fan_trees.hpp"

namespace hodt {

class DiamondEnds {
 public:
  static constexpr uint32_t kNone = 0;  // (no end: its multiplier stays 0)

  // members: the tile's vertices, their trees in t in order; position: per
  // vertex, its place in members (kNoFanNode: not a member).
  DiamondEnds(const FanTrees& t, const std::vector<uint32_t>& members, const std::vector<uint32_t>& position,
              const FanLister& lister);

  uint32_t at_node(uint64_t x) const { return at_node_[x]; }
  uint32_t at_leaf(uint64_t f) const { return at_leaf_[f]; }
  uint32_t member(uint32_t e) const { return member_[e]; }  // (its position in members)
  size_t size() const { return member_.size(); }             // (kNone included)
  // The two ends of every diamond both ends' vertices hold, members with fans
  // listed (the end at the smaller vertex first). An end without its other stays
  // unpaired, its multiplier 0.
  const std::vector<std::array<uint32_t, 2>>& pairs() const { return pairs_; }

 private:
  std::vector<uint32_t> at_node_, at_leaf_, member_;
  std::vector<std::array<uint32_t, 2>> pairs_;
};

}  // namespace hodt
