// The terms one fan of a vertex holds, for objectives summed over vertices or
// edges: a sum over triangulations is then a sum over vertices of a term of
// their fans (star_bound.hpp, fan_windows.hpp).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "hodt/mesh.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

// Vertex and edge sites only (not pairs or triangles).
inline bool fan_holds_terms(const ObjectiveTerms& d) {
  return d.site == TermSite::InteriorVertex || d.site == TermSite::Vertex || d.site == TermSite::InteriorEdge ||
         d.site == TermSite::Edge;
}

// Calls take(term) for each term of v's fan `ring` (its neighbours
// counterclockwise; cyclic round an interior vertex): v's own term, or the term
// of each edge v-u with both its triangles in the fan and owns(u) (an edge's
// term belongs to one of its ends). Hull edges hold none here (they are in
// every triangulation). Within a domain a fan decides which of its triangles
// are inside, so its terms are the domain's exactly: a vertex term reads the
// fan's triangles (consecutive neighbours), an edge term its two apexes.
template <class Owns, class Take>
void fan_terms(const Mesh& dt, const ObjectiveTerms& d, uint32_t v, const std::vector<uint32_t>& ring, bool cyclic,
               const Owns& owns, std::vector<uint32_t>& scratch, const Take& take) {
  const size_t m = ring.size();
  if (d.site == TermSite::InteriorVertex || d.site == TermSite::Vertex) {
    if (d.site == TermSite::Vertex || cyclic) {
      static thread_local std::vector<Tri> tris;
      tris.clear();
      if (reads_star_triangles(d))
        for (size_t j = 0; j + 1 < m || (cyclic && j < m); ++j) tris.push_back(Tri{v, ring[j], ring[(j + 1) % m]});
      scratch = ring;
      std::sort(scratch.begin(), scratch.end());
      take(vertex_term(d, dt, Star(v, scratch, tris)));
    }
    return;
  }
  for (size_t j = 0; j < m; ++j)
    if ((cyclic || (j > 0 && j + 1 < m)) && owns(ring[j]))
      take(edge_term(d, dt, v, ring[j], ring[(j + 1) % m], ring[(j + m - 1) % m]));
}

}  // namespace hodt
