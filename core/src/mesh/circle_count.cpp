#include "mesh/circle_count.hpp"

#include "hodt/predicates.hpp"

namespace hodt {

CircleCounter::CircleCounter(const Mesh& delaunay)
    : mesh_(delaunay), vertex_edge_(vertex_halfedges(delaunay)), mark_(delaunay.num_vertices(), 0) {}

uint32_t CircleCounter::count(uint32_t a, uint32_t b, uint32_t c, uint32_t limit) {
  if (++stamp_ == 0) {  // wrapped: clear the stamps
    std::fill(mark_.begin(), mark_.end(), 0);
    stamp_ = 1;
  }
  const double *pa = mesh_.point(a), *pb = mesh_.point(b), *pc = mesh_.point(c);
  queue_.assign({a, b, c});
  inside_.clear();
  for (uint32_t v : {a, b, c}) mark_[v] = stamp_;
  for (size_t head = 0; head < queue_.size(); ++head) {
    const uint32_t v = queue_[head];
    const uint32_t start = static_cast<uint32_t>(vertex_edge_[v]);
    uint32_t e = start;
    do {  // every neighbour of v: the targets of its outgoing halfedges, plus the
          // apex of the last one when v is on the hull
      const uint32_t w = mesh_.target(e);
      for (uint32_t u : {w, mesh_.apex(e)}) {
        if (mark_[u] == stamp_) continue;
        mark_[u] = stamp_;
        if (in_circle(pa, pb, pc, mesh_.point(u))) {
          inside_.push_back(u);
          if (inside_.size() > limit) return static_cast<uint32_t>(inside_.size());
          queue_.push_back(u);
        }
      }
      const int32_t t = mesh_.halfedges[prev_halfedge(e)];
      if (t < 0) break;
      e = static_cast<uint32_t>(t);
    } while (e != start);
  }
  return static_cast<uint32_t>(inside_.size());
}

}  // namespace hodt
