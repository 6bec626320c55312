// The pair measures with a cut (pair_measures.hpp) skip the accurate value when
// a float estimate shows the pair far below the cut. They must answer the
// measure itself, or a value <= cut when the measure is at most the cut: then
// the pruned models, and every solve, are those of the accurate measures.
#include <doctest/doctest.h>

#include "hodt/measures.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/terrain.hpp"
#include "exact/bottleneck.hpp"
#include "generators.hpp"
#include "objectives/pair_measures.hpp"

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

// The star filters: a star (here every vertex's triangles, and the same with
// a quad's flipped pair in) passes only if every pair in it measures at most the
// cut. Cuts at the star's largest pair value and within the filters' margins of
// it; passing where the cut is far above.
TEST_CASE("star filters: a star passes only when every pair is at most the cut") {
  size_t stars = 0, passed = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    std::vector<double> xyz = seed % 4 == 0 ? sliver_points(40, seed)
                              : seed % 4 == 1 ? dem_points(150, seed)
                              : seed % 4 == 2 ? jittered_grid(8, 7, 1e-9, seed)
                                              : grid_points(9, 8, seed);
    if (seed % 4 == 3)  // (a raster after reprojection, as in the benchmark)
      for (size_t i = 0; i < xyz.size(); i += 3) xyz[i] = 731012.3456789 + 74.98765 * xyz[i], xyz[i + 1] = 4100000.25 + 74.98765 * xyz[i + 1];
    if (seed > 36) {  // both ends of the coordinate range
      xyz = uniform_points(60, seed);
      for (double& v : xyz) v = (v + 0.1) * (seed % 2 ? 1e44 : 1e-44);
    }
    const Terrain t = Terrain::from_points(xyz);
    const FirstOrder& fo = t.structure();
    const Mesh& m = fo.base;
    const Stars st = build_stars(m);
    const VertexIncidence vi = vertex_incidence(fo);
    for (uint32_t v = 0; v < m.num_vertices(); ++v) {
      std::vector<Tri> star;
      for (uint32_t i = st.tri_offset[v]; i < st.tri_offset[v + 1]; ++i) star.push_back(base_triangle(m, st.triangle[i]));
      for (int with_flip = 0; with_flip < 2; ++with_flip) {
        if (with_flip) {  // a quad's other diagonal: its two triangles at v too
          if (vi.quads_begin(v) == vi.quads_end(v)) continue;
          Tri at[2];
          const uint32_t n = quad_triangles_at(fo, *vi.quads_begin(v), v, true, at);
          star.insert(star.end(), at, at + n);
        }
        double largest[2] = {0, 0};
        for (size_t i = 0; i < star.size(); ++i)
          for (size_t j = i + 1; j < star.size(); ++j) {
            largest[0] = std::max(largest[0], pair_area_ratio(m, star[i], star[j]));
            largest[1] = std::max(largest[1], pair_normal_angle(m, star[i], star[j]));
          }
        for (int k = 0; k < 2; ++k)
          for (double factor : {1 - 1e-7, 1 - 1e-12, 1 - 1e-15, 1.0, 1 + 1e-15, 1 + 1e-12, 1.5, 3.0}) {
            const double cut = k == 0 ? 1 + (largest[0] - 1) * factor : largest[1] * factor;
            const bool below = k == 0 ? star_area_ratio_below(m, star.data(), star.size(), cut)
                                      : star_normal_angle_below(m, star.data(), star.size(), cut);
            ++stars;
            if (below) {
              ++passed;
              CHECK(largest[k] <= cut);
            }
          }
      }
    }
  }
  MESSAGE(stars << " stars and cuts, " << passed << " passed");
  CHECK(passed > stars / 10);
}

// A pruned model (measures with a cut, the floor raised by every term's least
// value) keeps only what the search reads: the same thresholds, the same
// clauses in the same order, so the same answer as the full model, ties and all.
TEST_CASE("pair models: pruned, the bottleneck search answers as over the full model") {
  size_t steps = 0;
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    const int w = 4 + static_cast<int>(seed % 7);
    std::vector<double> xyz = seed % 4 == 0   ? dem_points(150, seed)
                              : seed % 4 == 1 ? grid_points(w, w + 1, seed, seed % 8 == 1)
                              : seed % 4 == 2 ? jittered_grid(w, w, 1e-9, seed)
                                              : grid_points(w + 2, w, seed);
    if (seed % 4 == 3)  // (a raster after reprojection: no coordinate an integer)
      for (size_t i = 0; i < xyz.size(); i += 3) xyz[i] = 731012.3456789 + 74.98765 * xyz[i], xyz[i + 1] = 4100000.25 + 74.98765 * xyz[i + 1];
    const Terrain t = Terrain::from_points(xyz);
    const FirstOrder& fo = t.structure();
    const Mesh& m = fo.base;
    auto ratio = [&](const Tri& s, const Tri& u, double cut) { return pair_area_ratio(m, s, u, cut); };
    auto angle = [&](const Tri& s, const Tri& u, double cut) { return pair_normal_angle(m, s, u, cut); };
    auto circle = [&](const Tri& s, const Tri& u, double cut) { return pair_enclosing_circle(m, s, u, cut); };
    auto star_ratio = [&](const Tri* t, size_t n, double cut) { return star_area_ratio_below(m, t, n, cut); };
    auto star_angle = [&](const Tri* t, size_t n, double cut) { return star_normal_angle_below(m, t, n, cut); };
    auto full_ratio = [&](const Tri& s, const Tri& u) { return pair_area_ratio(m, s, u); };
    auto full_angle = [&](const Tri& s, const Tri& u) { return pair_normal_angle(m, s, u); };
    auto full_circle = [&](const Tri& s, const Tri& u) { return pair_enclosing_circle(m, s, u); };
    const std::pair<BottleneckModel, BottleneckModel> models[] = {
        {edge_pair_model(fo, ratio), edge_pair_model(fo, full_ratio)},
        {edge_pair_model(fo, angle), edge_pair_model(fo, full_angle)},
        {edge_pair_model(fo, circle), edge_pair_model(fo, full_circle)},
        {vertex_pair_model(fo, ratio, {}, star_ratio), vertex_pair_model(fo, full_ratio)},
        {vertex_pair_model(fo, angle, {}, star_angle), vertex_pair_model(fo, full_angle)},
    };
    for (const auto& [pruned, full] : models) {
      CHECK(pruned.terms.size() <= full.terms.size());
      const BottleneckResult a = solve_bottleneck(pruned), b = solve_bottleneck(full);
      CHECK(a.value == b.value);
      CHECK(a.choice == b.choice);
      REQUIRE(a.trace.size() == b.trace.size());
      for (size_t i = 0; i < a.trace.size(); ++i) {
        CHECK(a.trace[i].threshold == b.trace[i].threshold);
        CHECK(a.trace[i].satisfiable == b.trace[i].satisfiable);
      }
      steps += a.trace.size();
    }
  }
  MESSAGE(steps << " threshold tests alike");
  CHECK(steps > 50);
}

// The critical pair found from the value expected (every pair below it cut
// short) is the one found without, and so is it when the expectation is wrong.
TEST_CASE("critical pair: the same pair with the value expected, right or wrong") {
  const Objective pair_objectives[] = {Objective::MinmaxEdgeAreaRatio, Objective::MinmaxEdgeNormalAngle,
                                       Objective::MinmaxEdgeEnclosingCircle, Objective::MinmaxVertexAreaRatio,
                                       Objective::MinmaxVertexNormalAngle};
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    std::vector<double> xyz = seed % 3 == 0 ? grid_points(7, 6, seed) : seed % 3 == 1 ? dem_points(80, seed) : sliver_points(30, seed);
    if (seed % 6 == 0)  // a raster after reprojection: pairs tie
      for (size_t i = 0; i < xyz.size(); i += 3) xyz[i] = 731012.3456789 + 74.98765 * xyz[i], xyz[i + 1] = 4100000.25 + 74.98765 * xyz[i + 1];
    const Terrain t = Terrain::from_points(xyz);
    const Mesh& m = t.structure().base;
    for (Objective o : pair_objectives) {
      const std::optional<CriticalPair> plain = critical_pair(o, m);
      REQUIRE(plain);
      for (double expected : {plain->value, plain->value * 2, plain->value / 2, std::nextafter(plain->value, INFINITY)}) {
        const std::optional<CriticalPair> c = critical_pair(o, m, {}, expected);
        REQUIRE(c);
        CHECK(c->value == plain->value);
        CHECK(c->first == plain->first);
        CHECK(c->second == plain->second);
      }
    }
  }
}
