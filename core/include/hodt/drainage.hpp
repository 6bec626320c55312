// The drainage network of one triangulation (DEFINITIONS.md, "Drainage"): water at a
// vertex runs down the steepest strictly descending edge; where no edge descends it
// stops, in a pit (interior) or leaves the terrain at an outlet. Every decision is
// exact (compare_descents in predicates.hpp); everything after the triangulation
// is linear in its size.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/terrain.hpp"

namespace hodt {

struct Drainage {
  // Per vertex: the neighbour it drains to, -1 if none (a pit or an outlet).
  std::vector<int32_t> downstream;
  // Per vertex: the pit or outlet its path down the network ends at.
  std::vector<int32_t> basin;
  // Per vertex: how many vertices' paths pass through it, its own included (for
  // a pit or an outlet, the size of its basin).
  std::vector<uint32_t> accumulation;
  // The vertices that drain nowhere, ascending: interior ones (pits) and those on
  // the convex hull or, within a domain, touching a triangle outside (outlets).
  std::vector<uint32_t> pits, outlets;
};

// The network of `mesh` (a valid triangulation: halfedges and hull linked), in its
// vertex indices. Two equally steep descents go to the neighbour of the smaller
// index: index[v] if given (one per vertex, distinct), else v. Within a domain
// (the mesh's coords.max_edge) water still runs along every edge; only the
// vertices that are not interior in the domain's sense (on the hull, or a corner
// of a triangle outside) become outlets.
Drainage drainage(const Mesh& mesh, const std::vector<uint32_t>& index = {});

// The same for a triangulation of a terrain's vertices (kept indices, as
// terrain.structure() and solve() give them) in the caller's input indices, by
// which ties are decided too: arrays per input point, a point dropped as a
// duplicate having no downstream, no basin (-1) and accumulation 0.
Drainage drainage(const Terrain& terrain, const Mesh& mesh);

}  // namespace hodt
