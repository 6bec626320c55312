#include "higher_order/bounds/diamond_ends.hpp"

#include <algorithm>

namespace hodt {

DiamondEnds::DiamondEnds(const FanTrees& t, const std::vector<uint32_t>& members, const std::vector<uint32_t>& position,
                         const FanLister& lister)
    : at_node_(t.corner.size(), kNone), at_leaf_(t.leaf.size(), kNone), member_(1, kNoFanNode) {
  using Key = std::array<uint32_t, 3>;  // (the neighbour, the one before it, the one after)
  std::vector<Key> key(1);              // per end
  std::vector<uint32_t> first_end(members.size() + 1, 1);
  std::vector<std::pair<Key, uint64_t>> slots;  // (a node, or a leaf with the top bit set)
  std::vector<uint32_t> first;                  // per node: the fan's first triangle's neighbour
  constexpr uint64_t kLeaf = uint64_t{1} << 63;
  for (uint32_t i = 0; i < members.size(); ++i) {
    first_end[i] = static_cast<uint32_t>(member_.size());
    const bool cyclic = lister.interior(members[i]);
    const uint64_t base = t.first_node[i];
    slots.clear();
    first.assign(t.first_node[i + 1] - base, kNoFanNode);
    for (uint64_t x = base; x < t.first_node[i + 1]; ++x) {
      const uint32_t y = t.parent[x];
      if (y == kNoFanNode) continue;
      const bool after_root = t.parent[y] == kNoFanNode;
      first[x - base] = after_root ? t.neighbor[x] : first[y - base];
      if (!after_root) slots.push_back({{t.neighbor[y], t.neighbor[t.parent[y]], t.neighbor[x]}, x});
      else if (!cyclic) slots.push_back({{t.neighbor[y], kNoFanNode, t.neighbor[x]}, x});  // (the hull edge first)
    }
    for (uint64_t f = t.first_leaf[i]; f < t.first_leaf[i + 1]; ++f) {
      const uint64_t z = t.leaf[f];
      const uint32_t before = t.neighbor[t.parent[z]];
      slots.push_back({{t.neighbor[z], before, cyclic ? first[z - base] : kNoFanNode}, f | kLeaf});
    }
    std::sort(slots.begin(), slots.end());
    for (size_t s = 0; s < slots.size(); ++s) {
      if (s == 0 || slots[s].first != slots[s - 1].first) key.push_back(slots[s].first), member_.push_back(i);
      const uint32_t e = static_cast<uint32_t>(member_.size() - 1);
      (slots[s].second & kLeaf ? at_leaf_[slots[s].second & ~kLeaf] : at_node_[slots[s].second]) = e;
    }
  }
  first_end[members.size()] = static_cast<uint32_t>(member_.size());
  // Each end's other end: at the neighbour, the diamond mirrored.
  for (uint32_t e = 1; e < member_.size(); ++e) {
    const uint32_t a = members[member_[e]], b = key[e][0];
    if (b < a || position[b] == kNoFanNode) continue;  // (each pair once, from its smaller end)
    const uint32_t j = position[b];  // (no fans listed: no ends, none found)
    const FanSide seen = mirrored({true, key[e][1], key[e][2]});
    const Key mirror{a, seen.before, seen.after};
    const auto from = key.begin() + first_end[j], to = key.begin() + first_end[j + 1];
    const auto it = std::lower_bound(from, to, mirror);
    if (it != to && *it == mirror) pairs_.push_back({e, static_cast<uint32_t>(it - key.begin())});
  }
}

}  // namespace hodt
