// The two families of pair models (included by bottleneck.hpp).
#pragma once
#include <algorithm>
#include <type_traits>

namespace hodt {

// A measure that takes a cut may answer any value <= cut for a pair whose value is
// at most cut (see pair_measures.hpp). Given the floor as cut, the model loses
// nothing the search needs, and is built pruned (BottleneckBuilder).
template <class Measure>
constexpr bool kTakesCut = std::is_invocable_v<Measure&, const Tri&, const Tri&, double>;

// Progress: a pair measured costs about this many work units (WorkCounter).
constexpr double kMeasureWork = 32;

template <class Measure>
double measure_above(Measure& measure, const Tri& s, const Tri& t, double cut) {
  if constexpr (kTakesCut<Measure>) return measure(s, t, cut);
  else return measure(s, t);
}

// Edge-adjacent pairs: the two triangles beside every interior edge of the
// triangulation. Fixed-fixed edges give the floor; an edge of a quad's boundary
// gives a term over that quad and the quad (if any) on the other side; a quad's
// own diagonal gives a unary term. The floor comes first, to prune the rest.
template <class Measure>
BottleneckModel edge_pair_model(const FirstOrder& fo, Measure measure, const Progress& progress) {
  const Mesh& m = fo.base;
  BottleneckBuilder b(fo.num_quads(), kTakesCut<Measure>, false);
  WorkCounter work;
  const double total = 2.0 * m.halfedges.size() + fo.num_quads();
  auto fixed = [&](uint32_t e) { return fo.quad_of_triangle[e / 3] < 0; };
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (f > static_cast<int32_t>(e) && fixed(e) && fixed(static_cast<uint32_t>(f)))
      b.constant(measure_above(measure, base_triangle(m, e / 3), base_triangle(m, static_cast<uint32_t>(f) / 3), b.floor()));
    if (work.tick(kMeasureWork)) report(progress, e, total);
  }
  const std::vector<uint8_t> diagonal = fo.diagonal_mask();
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    uint32_t t[2][6];
    fo.triangles_of(q, false, t[0]);
    fo.triangles_of(q, true, t[1]);
    double v[2];
    for (int x = 0; x < 2; ++x)
      v[x] = measure_above(measure, Tri{t[x][0], t[x][1], t[x][2]}, Tri{t[x][3], t[x][4], t[x][5]}, b.floor());
    b.unary(q, v[0], v[1]);
    if (work.tick(2 * kMeasureWork)) report(progress, m.halfedges.size() + q, total);
  }
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    if (work.tick(4 * kMeasureWork)) report(progress, m.halfedges.size() + fo.num_quads() + e, total);
    const int32_t f = m.halfedges[e];
    if (f < static_cast<int32_t>(e) || diagonal[e] || (fixed(e) && fixed(static_cast<uint32_t>(f)))) continue;
    const Side L = side_of(fo, e), R = side_of(fo, static_cast<uint32_t>(f));
    const double cut = b.floor();
    if (L.quad < 0 || R.quad < 0) {  // a quad beside a fixed triangle
      const Side& Q = L.quad >= 0 ? L : R;
      const Side& F = L.quad >= 0 ? R : L;
      b.unary(static_cast<uint32_t>(Q.quad), measure_above(measure, Q.tri[0], F.tri[0], cut),
              measure_above(measure, Q.tri[1], F.tri[0], cut));
    } else {  // two quads (a non-diagonal edge never has the same quad on both sides)
      double v[4];
      for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y) v[x + 2 * y] = measure_above(measure, L.tri[x], R.tri[y], cut);
      b.binary(static_cast<uint32_t>(L.quad), static_cast<uint32_t>(R.quad), v);
    }
  }
  return b.finish(progress);
}

// Vertex-adjacent pairs: all pairs of distinct triangles around each vertex. The
// floor (pairs of fixed triangles) comes first, to prune the rest. A star whose
// candidate triangles star_below(triangles, count, cut) shows all within the
// floor gives the builder its terms at the floor (pruned, in their place) without
// measuring its pairs: on a raster, four quads meet at every vertex.
template <class Measure, class StarBelow>
BottleneckModel vertex_pair_model(const FirstOrder& fo, Measure measure, const Progress& progress,
                                  StarBelow star_below) {
  const Mesh& m = fo.base;
  const VertexIncidence vi = vertex_incidence(fo);
  BottleneckBuilder b(fo.num_quads(), kTakesCut<Measure>, true);
  WorkCounter work;
  const double total = 2.0 * m.num_vertices();
  std::vector<Tri> fixed;
  auto fixed_at = [&](uint32_t v) {
    fixed.clear();
    for (uint32_t k = vi.fixed_offset[v]; k < vi.fixed_offset[v + 1]; ++k) fixed.push_back(base_triangle(m, vi.fixed[k]));
  };
  for (uint32_t v = 0; v < m.num_vertices(); ++v) {
    fixed_at(v);
    for (size_t i = 0; i < fixed.size(); ++i)
      for (size_t j = i + 1; j < fixed.size(); ++j) b.constant(measure_above(measure, fixed[i], fixed[j], b.floor()));
    if (work.tick(kMeasureWork * (1 + fixed.size() * fixed.size() / 2.0))) report(progress, v, total);
  }
  auto pair = [&](const Tri& s, const Tri& t) { return measure_above(measure, s, t, b.floor()); };
  // Each quad's own two triangles (a pair at both ends of its diagonal) before
  // the stars: the floor they raise prunes the stars' pairs from the start.
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    uint32_t t[2][6];
    fo.triangles_of(q, false, t[0]);
    fo.triangles_of(q, true, t[1]);
    double u[2];
    for (int x = 0; x < 2; ++x) u[x] = pair(Tri{t[x][0], t[x][1], t[x][2]}, Tri{t[x][3], t[x][4], t[x][5]});
    b.unary(q, u[0], u[1]);
  }
  std::vector<Tri> at[2];  // triangles of each quad at v, per choice
  std::vector<uint32_t> count[2];
  std::vector<Tri> star;   // every candidate at v
  for (uint32_t v = 0; v < m.num_vertices(); ++v) {
    const uint32_t* qs = vi.quads_begin(v);
    const uint32_t nq = static_cast<uint32_t>(vi.quads_end(v) - qs);
    if (nq == 0) continue;
    fixed_at(v);
    for (int x = 0; x < 2; ++x) {
      at[x].resize(2 * nq);
      count[x].resize(nq);
      for (uint32_t i = 0; i < nq; ++i) count[x][i] = quad_triangles_at(fo, qs[i], v, x, &at[x][2 * i]);
    }
    star = fixed;
    for (int x = 0; x < 2; ++x)
      for (uint32_t i = 0; i < nq; ++i) star.insert(star.end(), &at[x][2 * i], &at[x][2 * i] + count[x][i]);
    if (kTakesCut<Measure> && star_below(star.data(), star.size(), b.floor())) {
      const double f = b.floor(), w[4] = {f, f, f, f};
      for (uint32_t i = 0; i < nq; ++i) {
        b.unary(qs[i], f, f);
        for (uint32_t j = i + 1; j < nq; ++j) b.binary(qs[i], qs[j], w);
      }
      continue;
    }
    for (uint32_t i = 0; i < nq; ++i) {
      double u[2];
      for (int x = 0; x < 2; ++x) {
        u[x] = 0;
        const Tri* ti = &at[x][2 * i];
        if (count[x][i] == 2) u[x] = std::max(u[x], pair(ti[0], ti[1]));
        for (uint32_t a = 0; a < count[x][i]; ++a)
          for (const Tri& f : fixed) u[x] = std::max(u[x], pair(ti[a], f));
      }
      b.unary(qs[i], u[0], u[1]);
      for (uint32_t j = i + 1; j < nq; ++j) {
        double w[4];
        for (int x = 0; x < 2; ++x)
          for (int y = 0; y < 2; ++y) {
            double worst = 0;
            for (uint32_t a = 0; a < count[x][i]; ++a)
              for (uint32_t c = 0; c < count[y][j]; ++c) worst = std::max(worst, pair(at[x][2 * i + a], at[y][2 * j + c]));
            w[x + 2 * y] = worst;
          }
        b.binary(qs[i], qs[j], w);
      }
      if (work.tick(kMeasureWork * 4 * (fixed.size() + nq))) report(progress, m.num_vertices() + v, total);
    }
  }
  return b.finish(progress);
}

}  // namespace hodt
