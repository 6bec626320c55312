// Higher order Delaunay: useful k-OD edges and triangles (paper, Section 4.3;
// Gudmundsson, Hammar, van Kreveld, "Higher order Delaunay triangulations", CGTA 2002: Definitions 2, 3, Lemmas 1, 2).
//
// A triangle is k-OD if its circumcircle holds at most k points. By Lemma 1 an edge
// uv is a useful k-OD edge (in some k-OD triangulation) iff the triangles u v s1 and
// u v s2 are k-OD, where s1 is the point left of uv whose circle through u, v holds
// no point left of uv (s2 likewise on the right; a side without points is skipped).
// By Lemma 2 such an edge crosses at most 2k - 1 Delaunay edges, so candidates are
// found by walking the Delaunay triangulation from each vertex through at most
// 2k - 1 edges, keeping the wedge of directions that cross them all. s1 is among the
// left ends of the crossed edges; it is confirmed (and corrected, if ever needed) by
// walking the points inside its circle. Every decision is an exact predicate.
#pragma once
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/progress.hpp"

namespace hodt {

// Useful k-OD edges of the points of a Delaunay mesh, as sorted pairs (u < v).
// progress (if given) is called every few hundred vertices or edges; false cancels.
std::vector<std::pair<uint32_t, uint32_t>> useful_edges(const Mesh& delaunay, uint32_t k, const Progress& progress = {});

// The same with the least order at which each edge is useful (0: the Delaunay
// edges): Lemma 1's caps do not depend on k, so the useful j-OD edges for any
// j <= k are those of order at most j (the ladder's lower orders read them so).
struct UsefulEdges {
  std::vector<std::pair<uint32_t, uint32_t>> edges;  // sorted, u < v
  std::vector<uint8_t> order;                        // per edge
  std::vector<std::pair<uint32_t, uint32_t>> at(uint32_t j) const;
};
UsefulEdges useful_edges_by_order(const Mesh& delaunay, uint32_t k, const Progress& progress = {});

// k-OD triangles all of whose edges are useful k-OD edges, as sorted triples.
std::vector<std::array<uint32_t, 3>> useful_triangles(const Mesh& delaunay, uint32_t k,
                                                      const std::vector<std::pair<uint32_t, uint32_t>>& edges,
                                                      const Progress& progress = {});

// Is every triangle of the mesh k-OD (at most k points in its circumcircle)?
// (Scans with the Delaunay mesh's circle walk; `delaunay` must hold the same points.)
bool is_k_order(const Mesh& triangulation, const Mesh& delaunay, uint32_t k, const Progress& progress = {});

}  // namespace hodt
