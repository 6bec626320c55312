// The pair measures with a cut (pair_measures.hpp) skip the accurate value when
// a float estimate shows the pair far below the cut. They must answer the
// measure itself, or a value <= cut when the measure is at most the cut: then
// the pruned models, and every solve, are those of the accurate measures.
#include <doctest/doctest.h>

#include "generators.hpp"
#include "hodt/pair_measures.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/terrain.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("pair filters: the measure, or at most the cut when the measure is") {
  size_t pairs = 0, filtered = 0;
  for (uint64_t seed = 1; seed <= 36; ++seed) {
    std::vector<double> xyz = seed % 3 == 0 ? sliver_points(40, seed) : seed % 3 == 1 ? dem_points(200, seed)
                                                                                         : rotated_hull_points(30, 10, seed);
    // Steep random heights (angles past pi/2) at both ends of the coordinate range.
    if (seed > 30) {
      xyz = uniform_points(60, seed);
      for (double& v : xyz) v = (v + 0.1) * (seed % 2 ? 1e44 : 1e-44);
    }
    const Terrain t = Terrain::from_points(xyz);
    const Mesh& m = t.structure().base;
    Rng r(seed);
    for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
      const int32_t f = m.halfedges[e];
      if (f < static_cast<int32_t>(e)) continue;
      const Tri s = base_triangle(m, e / 3), u = base_triangle(m, static_cast<uint32_t>(f) / 3);
      const double value[3] = {pair_area_ratio(m, s, u), pair_normal_angle(m, s, u), pair_enclosing_circle(m, s, u)};
      for (int k = 0; k < 3; ++k) {
        // Cuts far below, near (both sides, within the filters' margins) and far above.
        for (double factor : {0.5, 1 - 1e-7, 1 - 1e-15, 1.0, 1 + 1e-15, 1 + 1e-7, 2.0, 1.0 + r.uniform()}) {
          const double cut = value[k] * factor;
          const double v = k == 0 ? pair_area_ratio(m, s, u, cut)
                           : k == 1 ? pair_normal_angle(m, s, u, cut)
                                    : pair_enclosing_circle(m, s, u, cut);
          ++pairs;
          if (v != value[k]) {
            ++filtered;
            CHECK(v <= cut);
            CHECK(value[k] <= cut);
          }
        }
      }
    }
  }
  MESSAGE(pairs << " pairs and cuts, " << filtered << " answered by a filter or a pruning");
  CHECK(filtered > pairs / 10);
}
