// The diamonds the star bound's multipliers sit on (diamond_ends.hpp): every
// k-OD triangulation's fans hold one end per neighbour, and at each edge the two
// ends of one pair. So each pair's two multipliers, summing to 0, are both in a
// triangulation or neither, and the bound holds for it. Against every k-OD
// triangulation of small instances.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <set>

#include "higher_order/bounds/diamond_ends.hpp"
#include "higher_order/bounds/fan_trees.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "k_order_reference.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("diamond ends: every k-OD triangulation's fans hold one end per neighbour, paired across each edge (k = 1 to 4)") {
  uint64_t triangulations = 0, edges_paired = 0;
  for_small_k_instances({1u, 2u, 3u, 4u}, 40, 23, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    const uint32_t n = dt.num_vertices();
    FanTrees t;
    FanLister lister(dt, structure.candidates, t);
    std::vector<uint32_t> members(n);
    for (uint32_t v = 0; v < n; ++v) {
      members[v] = v;
      t.first_node.push_back(t.corner.size()), t.first_leaf.push_back(t.leaf.size());
      REQUIRE(lister.list(v, 1'000'000));
    }
    t.first_node.push_back(t.corner.size()), t.first_leaf.push_back(t.leaf.size());
    const DiamondEnds ends(t, members, members, lister);  // (members[v] = v: each its own place)
    const std::set<std::array<uint32_t, 2>> pairs(ends.pairs().begin(), ends.pairs().end());
    for (const auto& [a, b] : ends.pairs()) CHECK(members[ends.member(a)] < members[ends.member(b)]);
    // Each vertex's fans by their rings.
    std::vector<std::map<std::vector<uint32_t>, uint64_t>> fan_of(n);
    std::vector<uint32_t> ring;
    for (uint32_t v = 0; v < n; ++v)
      for (uint64_t f = t.first_leaf[v]; f < t.first_leaf[v + 1]; ++f) t.ring(f, lister.interior(v), ring), fan_of[v][ring] = f;
    enumerate_k_order(dt, k, 1'000'000, [&](const std::vector<Tri>& tris) {
      CAPTURE(k);
      CAPTURE(seed);
      ++triangulations;
      const std::vector<std::vector<uint32_t>> rings = rings_of(mesh_of(dt.coords, tris));
      // Per vertex, its fan's end for each neighbour.
      std::vector<std::map<uint32_t, uint32_t>> end_at(n);
      for (uint32_t v = 0; v < n; ++v) {
        std::vector<uint32_t> r = rings[v];
        if (lister.interior(v)) std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());  // (fans start at the least)
        const auto it = fan_of[v].find(r);
        REQUIRE(it != fan_of[v].end());
        const uint64_t f = it->second;
        // A node holds the end at its parent's neighbour, the leaf the end at its own.
        end_at[v][t.neighbor[t.leaf[f]]] = ends.at_leaf(f);
        for (uint64_t x = t.leaf[f]; t.parent[x] != kNoFanNode; x = t.parent[x])
          if (ends.at_node(x) != DiamondEnds::kNone) end_at[v][t.neighbor[t.parent[x]]] = ends.at_node(x);
        CHECK(end_at[v].size() == r.size());  // (one end per neighbour)
        for (const auto& [u, e] : end_at[v]) CHECK(e != DiamondEnds::kNone);
      }
      // Every edge of the triangulation: the pair of its ends is a diamond.
      for (uint32_t v = 0; v < n; ++v)
        for (const uint32_t u : rings[v]) {
          if (u < v) continue;
          const bool found = pairs.count({end_at[v][u], end_at[u][v]});
          CHECK(found);
          edges_paired += found;
        }
    });
  });
  MESSAGE(triangulations << " k-OD triangulations, " << edges_paired << " edges with their diamond's ends paired");
  CHECK(triangulations > 1000);
}
