// Enumerating k-OD triangulations of a polygon of a Delaunay triangulation: an
// exact cover of its inside by candidate triangles (k-OD, every edge a useful
// k-OD edge, no point inside), grown from the open boundary edge with the fewest
// candidates. The whole convex hull, or one region (regions.hpp).
#pragma once
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/skeleton.hpp"
#include "engines/factor_graph.hpp"

namespace hodt {

inline uint64_t edge_key(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

// Candidate triangles by directed edge u -> v: the apexes w of the
// counterclockwise candidates u, v, w.
using Candidates = std::unordered_map<uint64_t, std::vector<uint32_t>>;
Candidates k_order_candidates(const Mesh& delaunay, uint32_t k,
                              const std::vector<std::pair<uint32_t, uint32_t>>& useful_edges,
                              const Progress& progress = {});

// The candidates whose three edges are all among `edges` (u < v): the same as
// k_order_candidates over that subset, without testing a circle again.
Candidates restrict_candidates(const Candidates& all, const std::vector<std::pair<uint32_t, uint32_t>>& edges);

// Do segments a b and c d cross at a point inside both (exact; sharing an
// endpoint is not crossing)?
bool segments_cross(const Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d);

// Calls visit for every triangulation of the polygon bounded by `boundary`
// (directed edges with the inside on their left) by candidate triangles. Returns
// false if it stopped because `max_nodes` search nodes were used. progress (if
// given) is called every few thousand nodes; returning false throws Cancelled.
bool enumerate_fills(const Mesh& delaunay, const Candidates& candidates,
                     const std::vector<std::pair<uint32_t, uint32_t>>& boundary, uint64_t max_nodes,
                     const std::function<void(const std::vector<Tri>&)>& visit, const Progress& progress = {},
                     uint64_t* nodes_used = nullptr);

}  // namespace hodt
