// The domain of a terrain (docs/objectives.md, "The domain"): an optional plane
// length max_edge, kept with the points (Coords::max_edge). A triangle is inside
// when each of its edges is at most max_edge long; only inside triangles are
// measured. The triangulations themselves are unchanged.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "hodt/first_order.hpp"
#include "hodt/mesh.hpp"
#include "hodt/predicates.hpp"
#include "hodt/skeleton.hpp"

namespace hodt {

inline bool has_domain(const Mesh& m) { return m.coords.max_edge() < INFINITY; }

// Is the plane length of uv at most max_edge? (Exact; true without a domain.)
inline bool edge_inside(const Mesh& m, uint32_t u, uint32_t v) {
  return !has_domain(m) || compare_length(m.point(u), m.point(v), m.coords.max_edge()) <= 0;
}
// Are all three edges of t inside?
inline bool triangle_inside(const Mesh& m, const Tri& t) {
  return !has_domain(m) || (edge_inside(m, t[0], t[1]) && edge_inside(m, t[1], t[2]) && edge_inside(m, t[2], t[0]));
}
// Per triangle of m: 1 if inside (all 1 without a domain).
std::vector<uint8_t> inside_triangles(const Mesh& m);

// Per quad of fo: 1 if one of its four triangles (two per diagonal) is outside,
// i.e. one of its four sides or two diagonals is longer than max_edge. Every other
// quad has both triangles inside whatever it chooses. (All 0 without a domain.)
std::vector<uint8_t> quads_touching_outside(const FirstOrder& fo);

// At order k: per vertex of the Delaunay triangulation, 1 if it is a corner of a
// triangle over `useful` edges (and Delaunay edges) with an edge longer than
// max_edge. Every edge of a k-OD triangulation is useful, so each k-OD
// triangle at a vertex marked 0 is inside: its star is inside in every k-OD
// triangulation, and its term is the one without a domain. (All 0 without a
// domain.)
std::vector<uint8_t> vertices_near_outside(const Mesh& delaunay, const std::vector<std::pair<uint32_t, uint32_t>>& useful);

// A warning when the domain leaves almost nothing to measure: at most 1% of the
// Delaunay triangulation's triangles inside (none at all included). It names
// how many are inside and the points' typical spacing, the median Delaunay edge
// length, to compare max_edge with. Nothing without a domain or with more inside.
std::optional<std::string> empty_domain_warning(const Mesh& dt);

// Checks a max_edge given by a caller: a positive number, or infinity for none
// (InputError naming the value otherwise).
void check_max_edge(double max_edge);

// For rasters: the default max_edge is this many times the larger cell side. It
// keeps every triangle of a full grid up to order 8 or so (edges of 1, 1.41, 2.24
// and 2.83 cells) and a bridge over a one- or two-cell hole, and drops every
// triangle that reaches across a wider NODATA area.
constexpr double kRasterMaxEdgeCells = 3;

}  // namespace hodt
