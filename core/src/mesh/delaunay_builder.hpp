// The incremental Delaunay triangulator shared by delaunay() and the local edits
// (delaunay_edit.cpp). Private to the core.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/predicates.hpp"

namespace hodt {

// A halfedge of the triangle containing q with q on it or to its right (then it is
// a hull edge and q is outside); else q is strictly inside its triangle. A
// visibility walk from halfedge `start`'s triangle (it terminates in any Delaunay
// triangulation).
inline uint32_t locate(const Mesh& m, const double* q, uint32_t start) {
  uint32_t t = start / 3, came = UINT32_MAX;
  for (;;) {
    uint32_t on = UINT32_MAX, crossed = UINT32_MAX;
    for (uint32_t k = 0; k < 3; ++k) {
      const uint32_t e = 3 * t + k;
      if (e == came) continue;
      const int o = orient2d(m.point(m.origin(e)), m.point(m.target(e)), q);
      if (o < 0) {
        crossed = e;
        break;
      }
      if (o == 0) on = e;
    }
    if (crossed == UINT32_MAX) return on != UINT32_MAX ? on : 3 * t;
    const int32_t f = m.halfedges[crossed];
    if (f < 0) return crossed;
    came = static_cast<uint32_t>(f);
    t = came / 3;
  }
}

// Incremental Delaunay triangulation written straight into the flat arrays:
// points arrive along a space-filling curve, each is located by a walk from the
// previous one, joined to
// the triangle, edge or visible hull edges it falls on, and the new triangles are
// made Delaunay by Lawson flips. Decisions use the exact predicates, in-circle with
// CGAL's symbolic perturbation, so the result is the unique triangulation CGAL's
// Delaunay_triangulation_2 builds (checked against it in tests/core).
class Builder {
 public:
  // touched (optional) receives every triangle slot written, with repeats.
  explicit Builder(Mesh& m, std::vector<uint32_t>* touched = nullptr) : m_(m), touched_(touched) {}
  void start_near(uint32_t triangle) { last_ = 3 * triangle; }

  void seed(uint32_t a, uint32_t b, uint32_t c) {
    if (orient2d(pt(a), pt(b), pt(c)) < 0) std::swap(b, c);
    const uint32_t t = new_triangle();
    set(t, a, b, c);
    last_ = 3 * t;
  }

  void insert(uint32_t p) {
    const double* q = pt(p);
    const uint32_t e = hodt::locate(m_, q, last_);
    chain_.clear();
    reuse_.clear();
    bool closed = true;
    const int o = orient2d(pt(m_.origin(e)), pt(m_.target(e)), q);
    if (o < 0) {  // outside the hull: e is a visible hull edge
      // The visible hull edges are contiguous; collect them in hull order.
      uint32_t first = e, last = e;
      for (uint32_t h = prev_hull(first); orient2d(pt(m_.origin(h)), pt(m_.target(h)), q) < 0; h = prev_hull(h)) first = h;
      for (uint32_t h = next_hull(last); orient2d(pt(m_.origin(h)), pt(m_.target(h)), q) < 0; h = next_hull(h)) last = h;
      // New triangles (v, u, p) over each visible u -> v, counterclockwise around p.
      for (uint32_t h = last;; h = prev_hull(h)) {
        chain_.push_back({m_.target(h), m_.origin(h), static_cast<int32_t>(h)});
        if (h == first) break;
      }
      closed = false;
    } else if (o == 0) {  // on edge e (p is strictly inside the other two sides)
      const int32_t f = m_.halfedges[e];
      push_side(next_halfedge(e)), push_side(prev_halfedge(e));
      reuse_.push_back(e / 3);
      if (f >= 0) {
        push_side(next_halfedge(static_cast<uint32_t>(f))), push_side(prev_halfedge(static_cast<uint32_t>(f)));
        reuse_.push_back(static_cast<uint32_t>(f) / 3);
      } else {
        closed = false;  // a hull edge: p joins the hull between its ends
      }
    } else {  // strictly inside e's triangle
      const uint32_t t = e / 3;
      for (uint32_t k = 0; k < 3; ++k) push_side(3 * t + k);
      reuse_.push_back(t);
    }
    fan(p, closed);
  }

  // The hull (counterclockwise, from its smallest vertex) from the twinless halfedges.
  void finish() {
    uint32_t start = UINT32_MAX;
    for (uint32_t e = 0; e < m_.halfedges.size(); ++e)
      if (m_.halfedges[e] < 0 && (start == UINT32_MAX || m_.origin(e) < m_.origin(start))) start = e;
    m_.hull.clear();
    uint32_t e = start;
    do {
      m_.hull.push_back(m_.origin(e));
      e = next_hull(e);
    } while (e != start);
  }

 private:
  struct Side {
    uint32_t from, to;
    int32_t twin;  // the halfedge on the other side, -1 on the hull
  };

  const double* pt(uint32_t v) const { return m_.point(v); }

  uint32_t new_triangle() {
    m_.triangles.resize(m_.triangles.size() + 3);
    m_.halfedges.resize(m_.halfedges.size() + 3, -1);
    return m_.num_triangles() - 1;
  }
  void set(uint32_t t, uint32_t a, uint32_t b, uint32_t c) {
    m_.triangles[3 * t] = a, m_.triangles[3 * t + 1] = b, m_.triangles[3 * t + 2] = c;
    if (touched_) touched_->push_back(t);
  }
  void link(uint32_t e, int32_t f) {
    m_.halfedges[e] = f;
    if (f >= 0) m_.halfedges[static_cast<uint32_t>(f)] = static_cast<int32_t>(e);
  }
  void push_side(uint32_t e) { chain_.push_back({m_.origin(e), m_.target(e), m_.halfedges[e]}); }

  // The next / previous hull halfedge, turning around the shared vertex.
  uint32_t next_hull(uint32_t e) const {
    uint32_t g = next_halfedge(e);
    while (m_.halfedges[g] >= 0) g = next_halfedge(static_cast<uint32_t>(m_.halfedges[g]));
    return g;
  }
  uint32_t prev_hull(uint32_t e) const {
    uint32_t g = prev_halfedge(e);
    while (m_.halfedges[g] >= 0) g = prev_halfedge(static_cast<uint32_t>(m_.halfedges[g]));
    return g;
  }

  // Joins p to the sides in chain_ (consecutive: each ends where the next begins,
  // counterclockwise around p; the last joins the first if closed), reusing the
  // replaced triangles' slots, then restores the Delaunay property.
  void fan(uint32_t p, bool closed) {
    const size_t k = chain_.size();
    tris_.clear();
    for (size_t i = 0; i < k; ++i) {
      const uint32_t t = i < reuse_.size() ? reuse_[i] : new_triangle();
      set(t, chain_[i].from, chain_[i].to, p);
      link(3 * t, chain_[i].twin);
      tris_.push_back(t);
    }
    for (size_t i = 0; i + 1 < k; ++i) link(3 * tris_[i] + 1, static_cast<int32_t>(3 * tris_[i + 1] + 2));
    if (closed) {
      link(3 * tris_[k - 1] + 1, static_cast<int32_t>(3 * tris_[0] + 2));
    } else {
      m_.halfedges[3 * tris_[0] + 2] = -1;
      m_.halfedges[3 * tris_[k - 1] + 1] = -1;
    }
    for (uint32_t t : tris_) legalize(3 * t);
    last_ = 3 * tris_[0];
  }

  // Lawson flips: halfedge a has p as its apex; while the point beyond a is inside
  // the circle of a's triangle, flip and check the two edges now facing p.
  void legalize(uint32_t a) {
    stack_.push_back(a);
    while (!stack_.empty()) {
      const uint32_t e = stack_.back();
      stack_.pop_back();
      const int32_t f = m_.halfedges[e];
      if (f < 0) continue;
      const uint32_t b = static_cast<uint32_t>(f);
      if (!in_circle(pt(m_.origin(e)), pt(m_.target(e)), pt(m_.apex(e)), pt(m_.apex(b)))) continue;
      flip_edge(m_, e);  // see mesh.hpp: p is now the apex of prev(e) and next(b)
      if (touched_) touched_->push_back(e / 3), touched_->push_back(b / 3);
      stack_.push_back(prev_halfedge(e));
      stack_.push_back(next_halfedge(b));
    }
  }

  Mesh& m_;
  std::vector<uint32_t>* touched_;
  uint32_t last_ = 0;
  std::vector<Side> chain_;
  std::vector<uint32_t> reuse_, tris_, stack_;
};


}  // namespace hodt
