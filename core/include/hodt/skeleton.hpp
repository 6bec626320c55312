// The skeleton of a first order structure: the base triangulation without its
// flippable diagonals, i.e. fixed triangles and flippable quads. Every solver
// builds its model from these local views: which triangle lies beside an edge, and
// which triangles touch a vertex, as a function of the quads' choices.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "hodt/first_order.hpp"

namespace hodt {

using Tri = std::array<uint32_t, 3>;  // vertex indices, counterclockwise

// The triangle on the left of base halfedge e (not a quad diagonal): fixed
// (quad = -1, tri[0] == tri[1]) or the triangle of `quad` for choice 0 and 1.
struct Side {
  int32_t quad;
  Tri tri[2];
};
Side side_of(const FirstOrder& fo, uint32_t e);

// The triangles of quad q that contain vertex v, for one choice (1 or 2 of them).
uint32_t quad_triangles_at(const FirstOrder& fo, uint32_t q, uint32_t v, bool flipped, Tri out[2]);

// Per vertex: the quads it belongs to and its fixed triangles, in compressed rows.
struct VertexIncidence {
  std::vector<uint32_t> quad_offset, quads;
  std::vector<uint32_t> fixed_offset, fixed;  // base triangle indices
  const uint32_t* quads_begin(uint32_t v) const { return quads.data() + quad_offset[v]; }
  const uint32_t* quads_end(uint32_t v) const { return quads.data() + quad_offset[v + 1]; }
};
VertexIncidence vertex_incidence(const FirstOrder& fo);

// The larger plane area of quad q's two triangles for one choice.
double largest_triangle(const FirstOrder& fo, uint32_t q, bool flipped);

// The same triangle rotated to start at its smallest vertex (orientation kept):
// equal triangles listed from different corners compare equal.
inline Tri canonical_triangle(Tri t) {
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

inline Tri base_triangle(const Mesh& m, uint32_t t) {
  return {m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]};
}

}  // namespace hodt
