// A triangulation as flat arrays, in delaunator's layout: triangle t has the
// halfedges 3t, 3t+1, 3t+2; halfedge e runs from triangles[e] to
// triangles[next_halfedge(e)]; halfedges[e] is its twin or -1 on the hull.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace hodt {

inline uint32_t next_halfedge(uint32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
inline uint32_t prev_halfedge(uint32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }

// Vertex coordinates x, y, z: one array shared by copies (a triangulation and the
// flips of it made by triangulate() hold the same points), copied on write.
class Coords {
 public:
  Coords() : v_(std::make_shared<std::vector<double>>()) {}
  Coords(std::vector<double> v) : v_(std::make_shared<std::vector<double>>(std::move(v))) {}  // NOLINT: implicit by design
  const std::vector<double>& vector() const { return *v_; }
  operator const std::vector<double>&() const { return *v_; }  // NOLINT
  size_t size() const { return v_->size(); }
  const double* data() const { return v_->data(); }
  double operator[](size_t i) const { return (*v_)[i]; }
  // The array to modify, unshared first.
  std::vector<double>& write() {
    if (v_.use_count() > 1) v_ = std::make_shared<std::vector<double>>(*v_);
    return *v_;
  }
  // The domain (domain.hpp): triangles with an edge longer than this (in the
  // plane) are outside. It travels with the points, so every triangulation of
  // them is measured the same way. Infinity: no domain.
  double max_edge() const { return max_edge_; }
  void set_max_edge(double max_edge) { max_edge_ = max_edge; }

 private:
  std::shared_ptr<std::vector<double>> v_;
  double max_edge_ = INFINITY;
};

struct Mesh {
  Coords coords;                    // x, y, z per vertex
  std::vector<uint32_t> triangles;  // 3 vertices per triangle, counterclockwise
  std::vector<int32_t> halfedges;   // twin halfedge, -1 on the hull
  std::vector<uint32_t> hull;       // hull vertices, counterclockwise

  uint32_t num_vertices() const { return static_cast<uint32_t>(coords.size() / 3); }
  uint32_t num_triangles() const { return static_cast<uint32_t>(triangles.size() / 3); }
  const double* point(uint32_t v) const { return coords.data() + 3 * size_t(v); }
  uint32_t origin(uint32_t e) const { return triangles[e]; }
  uint32_t target(uint32_t e) const { return triangles[next_halfedge(e)]; }
  // The vertex of e's triangle that is not on e.
  uint32_t apex(uint32_t e) const { return triangles[prev_halfedge(e)]; }
};

// Flips the diagonal of the convex quadrilateral formed by the two triangles of
// interior halfedge e (delaunator's legalize step). Afterwards halfedge e and its
// twin are still the two halves of the new diagonal, so flipping e again restores
// the original triangles (up to the rotation of their vertex lists).
void flip_edge(Mesh& mesh, uint32_t e);

// Puts the triangles in a canonical order (each triangle starts at its smallest
// vertex; triangles sorted by first, then second vertex), so that equal
// triangulations give identical arrays on every platform. Halfedges are renumbered
// if present, else linked (with the hull) by link_halfedges.
void canonicalize(Mesh& mesh);

// Rebuilds halfedges and hull from triangles. Returns an error message (empty if
// none) if two triangles use the same directed edge or an edge is shared thrice.
std::string link_halfedges(Mesh& mesh);

// One outgoing halfedge per vertex, a hull halfedge for hull vertices, so that
// walking twin(prev(e)) from it visits the whole star counterclockwise.
std::vector<int32_t> vertex_halfedges(const Mesh& mesh);

// Walks the star of a vertex counterclockwise from its halfedge `start`
// (vertex_halfedges): neighbour(w, t) for each neighbour w with the triangle t
// that follows it, the last neighbour of a hull vertex with t = UINT32_MAX.
template <class Neighbour>
void walk_star(const Mesh& m, uint32_t start, Neighbour neighbour) {
  uint32_t e = start;
  for (;;) {
    neighbour(m.target(e), e / 3);
    const int32_t t = m.halfedges[prev_halfedge(e)];
    if (t < 0) {
      neighbour(m.apex(e), UINT32_MAX);
      return;
    }
    e = static_cast<uint32_t>(t);
    if (e == start) return;
  }
}

// Checks every invariant: triangles counterclockwise and non-degenerate, halfedges
// symmetric and matching, hull a counterclockwise cycle of the twinless halfedges.
// Returns an empty string if valid, else what is wrong.
std::string validate(const Mesh& mesh);

}  // namespace hodt
