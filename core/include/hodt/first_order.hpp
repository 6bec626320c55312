// The first order structure: flippable quads and fixed edges. The first order
// Delaunay triangulations are exactly the 2^m choices of a diagonal per quad.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt {

struct Quad {
  uint32_t a, b;  // the base diagonal (the Delaunay edge)
  uint32_t c, d;  // the other diagonal: c left of a -> b, d right
  uint32_t edge;  // halfedge a -> b of the base mesh (its triangle is a, b, c)
};

// A choice is one byte per quad: 0 = base (Delaunay) diagonal, 1 = flipped.
using Choice = std::vector<uint8_t>;

struct FirstOrder {
  Mesh base;                              // the triangulation of choice 0
  std::vector<Quad> quads;                // ordered by base halfedge
  std::vector<int32_t> quad_of_triangle;  // base triangle -> its quad, -1 if fixed
  bool is_delaunay = true;                // base is the Delaunay triangulation

  uint32_t num_quads() const { return static_cast<uint32_t>(quads.size()); }
  // Vertices of the two triangles of quad q for one choice, counterclockwise.
  void triangles_of(uint32_t q, bool flipped, uint32_t out[6]) const;
  // Per base halfedge: 1 if it is (half of) a quad's Delaunay diagonal.
  std::vector<uint8_t> diagonal_mask() const;
};

// Flippable quads of a Delaunay mesh: interior edge ab with triangles abc, abd is
// flippable iff acbd is strictly convex and the triangles adc, dbc each have at
// most one point inside their circumcircle (decided with the perturbed in_circle).
FirstOrder first_order(Mesh delaunay);

// The same, one edge at a time (for local updates): is the interior edge of
// halfedge e flippable? out = vertex_halfedges(delaunay).
bool flippable(const Mesh& delaunay, const std::vector<int32_t>& out, uint32_t e);
// The structure from a mark per halfedge (1 on the smaller halfedge of each
// flippable edge).
FirstOrder first_order_of_marked(Mesh delaunay, const std::vector<uint8_t>& marked);

// A singly-flippable triangulation: the user's triangles (either orientation) of
// the points in `coords`, with designated flippable edges (pairs of vertices).
// Throws InputError naming the triangle, edge or vertex that is wrong: triangles
// must triangulate the convex hull using every point; each designated edge must
// be an interior edge whose quad is strictly convex, no triangle touching two.
FirstOrder singly_flippable(std::vector<double> coords, const std::vector<uint32_t>& triangles,
                            const std::vector<uint32_t>& flippable_edges);

// The triangulation of a choice: the base with the chosen quads flipped.
// Triangle and halfedge slots keep their meaning (quad q stays in its two slots).
Mesh triangulate(const FirstOrder& fo, const Choice& choice);

// Number of quads not on their base diagonal.
uint32_t count_flipped(const Choice& choice);

}  // namespace hodt
