// NeighbourhoodClasses answers vertex_class for every subset of optional
// candidates from one look at the triangles of candidates: checked against
// vertex_class on each subset, on data where classes tie and degenerate (equal
// heights, flat ground, cocircular rasters at an offset, slivers).
#include <doctest/doctest.h>

#include "hodt/measures.hpp"
#include "hodt/terrain.hpp"
#include "generators.hpp"
#include "objectives/neighbourhood_classes.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("neighbourhood classes: each subset of candidates as vertex_class classifies it") {
  size_t checked = 0, direct_answers = 0;
  uint32_t seen[5] = {0, 0, 0, 0, 0};
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    std::vector<double> xyz = seed % 5 == 0   ? dem_points(60, seed)
                              : seed % 5 == 1 ? grid_points(6, 6, seed, true)  // equal heights in places
                              : seed % 5 == 2 ? sliver_points(30, seed)
                              : seed % 5 == 3 ? grid_points(7, 6, seed)
                                              : uniform_points(40, seed);
    if (seed % 5 == 3)  // a raster after reprojection
      for (size_t i = 0; i < xyz.size(); i += 3) xyz[i] = 731012.3456789 + 74.98765 * xyz[i], xyz[i + 1] = 4100000.25 + 74.98765 * xyz[i + 1];
    if (seed % 10 == 4)  // flat ground
      for (size_t i = 2; i < xyz.size(); i += 3) xyz[i] = 7;
    const Terrain t = Terrain::from_points(xyz);
    const Mesh& m = t.structure().base;
    const Stars st = build_stars(m);
    Rng r(seed);
    for (uint32_t v = 0; v < m.num_vertices(); ++v) {
      if (st.on_hull[v]) continue;
      // Candidates: the neighbours and some of theirs; a random part fixed.
      std::vector<uint32_t> cand;
      for (uint32_t k = st.offset[v]; k < st.offset[v + 1]; ++k) {
        const uint32_t w = st.neighbor[k];
        if (std::find(cand.begin(), cand.end(), w) == cand.end()) cand.push_back(w);
        const uint32_t x = st.neighbor[st.offset[w] + static_cast<uint32_t>(r.below(static_cast<int>(st.degree(w))))];
        if (x != v && std::find(cand.begin(), cand.end(), x) == cand.end()) cand.push_back(x);
      }
      std::vector<const double*> fixed, optional;
      for (uint32_t w : cand) (optional.size() < 9 && r.below(3) ? optional : fixed).push_back(m.point(w));
      const NeighbourhoodClasses classes(m.point(v), fixed, optional);
      for (uint32_t mask = 0; mask < (1u << optional.size()); ++mask) {
        std::vector<const double*> nb = fixed;
        for (uint32_t i = 0; i < optional.size(); ++i)
          if ((mask >> i) & 1) nb.push_back(optional[i]);
        if (nb.size() < 3) continue;
        const VertexClass expected = vertex_class(m.point(v), nb.data(), static_cast<uint32_t>(nb.size()));
        CHECK(classes.of(mask) == expected);
        ++checked, ++seen[expected];
        direct_answers += expected == kFlat;
      }
    }
  }
  MESSAGE(checked << " neighbourhoods: " << seen[kConvex] << " convex, " << seen[kConcave] << " concave, "
                  << seen[kFlat] << " flat, " << seen[kMixed] << " mixed");
  CHECK(seen[kConvex] > 100);
  CHECK(seen[kConcave] > 100);
  CHECK(seen[kMixed] > 100);
  CHECK(direct_answers > 10);
}
