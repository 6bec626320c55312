#include "mesh/raster_delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "hodt/predicates.hpp"
#include "containers/flat_index.hpp"

namespace hodt {

namespace {

// The distinct values of one coordinate, each with its rank once sorted.
struct Lines {
  FlatIndex index;  // bits of the value (-0 as +0) -> rank
  std::vector<double> values;
  static uint64_t key(double v) {
    v += 0.0;  // -0 -> +0
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
  }
  void add(double v) {
    if (index.find(key(v)) == FlatIndex::kNone) index.insert(key(v), 0), values.push_back(v);
  }
  void rank() {
    std::sort(values.begin(), values.end());
    index.clear();
    for (uint32_t i = 0; i < values.size(); ++i) index.insert(key(values[i]), i);
  }
  uint32_t operator[](double v) const { return index.find(key(v)); }
};

}  // namespace

bool raster_delaunay(Mesh& m) {
  const size_t n = m.num_vertices();
  if (n < 4) return false;
  auto p = [&](uint32_t v) { return m.point(v); };
  // A lattice of n nodes has columns * rows = n: one of them is at most sqrt(n).
  const size_t fewer = static_cast<size_t>(std::sqrt(static_cast<double>(n))) + 1;
  Lines cols, rows;
  for (uint32_t i = 0; i < n; ++i) {
    cols.add(p(i)[0]);
    rows.add(p(i)[1]);
    if (cols.values.size() > fewer && rows.values.size() > fewer) return false;
  }
  const size_t nx = cols.values.size(), ny = rows.values.size();
  if (nx < 2 || ny < 2 || nx * ny != n) return false;
  cols.rank();
  rows.rank();
  // Every node once (n distinct points on nx * ny nodes: all of them, if no two
  // points share one).
  std::vector<uint32_t> node(n, UINT32_MAX);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t& at = node[rows[p(i)[1]] * nx + cols[p(i)[0]]];
    if (at != UINT32_MAX) return false;
    at = i;
  }
  // The first cell decides the diagonal for all: corners a (low x, low y), b, c, d
  // counterclockwise. Diagonal ac when it is locally Delaunay from both sides, bd
  // when that one is; either way exactly one (else leave it to the general
  // construction).
  const uint32_t a = node[0], b = node[1], c = node[nx + 1], d = node[nx];
  const bool ac = !in_circle(p(a), p(b), p(c), p(d)) && !in_circle(p(c), p(d), p(a), p(b));
  const bool bd = !in_circle(p(b), p(c), p(d), p(a)) && !in_circle(p(d), p(a), p(b), p(c));
  if (ac == bd) return false;
  // Cell k = j (nx - 1) + i has triangles 2k, 2k + 1 and halfedges 6k .. 6k + 5:
  // with ac, (a b c) (a c d); with bd, (a b d) (b c d). Where its sides are:
  const uint32_t bottom = 0, right = ac ? 1 : 3, top = 4, left = ac ? 5 : 2;
  const uint32_t diagonal[2] = {ac ? 2u : 1u, ac ? 3u : 5u};
  const size_t cells = (nx - 1) * (ny - 1);
  m.triangles.resize(6 * cells);
  m.halfedges.assign(6 * cells, -1);
  for (size_t j = 0; j + 1 < ny; ++j)
    for (size_t i = 0; i + 1 < nx; ++i) {
      const size_t k = j * (nx - 1) + i;
      const uint32_t a0 = node[j * nx + i], b0 = node[j * nx + i + 1], c0 = node[(j + 1) * nx + i + 1],
                     d0 = node[(j + 1) * nx + i];
      uint32_t* t = &m.triangles[6 * k];
      if (ac) t[0] = a0, t[1] = b0, t[2] = c0, t[3] = a0, t[4] = c0, t[5] = d0;
      else t[0] = a0, t[1] = b0, t[2] = d0, t[3] = b0, t[4] = c0, t[5] = d0;
      int32_t* h = &m.halfedges[6 * k];
      h[diagonal[0]] = static_cast<int32_t>(6 * k + diagonal[1]);
      h[diagonal[1]] = static_cast<int32_t>(6 * k + diagonal[0]);
      if (j > 0) h[bottom] = static_cast<int32_t>(6 * (k - (nx - 1)) + top);
      if (j + 2 < ny) h[top] = static_cast<int32_t>(6 * (k + (nx - 1)) + bottom);
      if (i > 0) h[left] = static_cast<int32_t>(6 * (k - 1) + right);
      if (i + 2 < nx) h[right] = static_cast<int32_t>(6 * (k + 1) + left);
    }
  // The hull: bottom row, right column, top row back, left column down.
  m.hull.clear();
  for (size_t i = 0; i + 1 < nx; ++i) m.hull.push_back(node[i]);
  for (size_t j = 0; j + 1 < ny; ++j) m.hull.push_back(node[j * nx + nx - 1]);
  for (size_t i = nx - 1; i > 0; --i) m.hull.push_back(node[(ny - 1) * nx + i]);
  for (size_t j = ny - 1; j > 0; --j) m.hull.push_back(node[j * nx]);
  std::rotate(m.hull.begin(), std::min_element(m.hull.begin(), m.hull.end()), m.hull.end());
  return true;
}

}  // namespace hodt
