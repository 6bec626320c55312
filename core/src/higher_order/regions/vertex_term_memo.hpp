// Vertex terms remembered by their stars' neighbours, across the region models
// of one solve: each model evaluates every star a combination of its regions'
// fans gives, and the models of one solve (the engine's, rebuilt with more
// states, the duals' and the views') meet the same stars again, so each star's
// term is evaluated once per solve rather than once per model (while the memo
// has room, below).
//
// Over the convex hull the star of v in a triangulation is the fan over its
// neighbours in angular order (the triangles around v tile a neighbourhood of
// it, or at a hull vertex the wedge inside the hull), so the neighbours decide
// the term. Within a domain too: the triangulations still cover the hull, so
// the neighbours decide the star's triangles, and with them which are inside.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hodt {

class VertexTermMemo {
 public:
  // Up to max_stars stars are remembered (about 60 bytes each: 120 MB at the
  // default, at about a dozen distinct stars per point at k = 4 enough for a
  // terrain of over 100,000 points at that order); past it,
  // terms are evaluated each time.
  explicit VertexTermMemo(size_t max_stars = size_t(1) << 21) : max_stars_(max_stars) {}

  // The term of v's star with these neighbours (sorted, each once): the one
  // remembered, else eval(), remembered.
  template <class Eval>
  double operator()(uint32_t v, const std::vector<uint32_t>& neighbors, Eval eval) {
    const uint64_t h = hash(v, neighbors.data(), neighbors.size());
    double value;
    if (find(v, neighbors, h, value)) return value;
    value = eval();
    insert(v, neighbors, h, value);
    return value;
  }

  size_t size() const { return stars_; }

 private:
  static uint64_t hash(uint32_t v, const uint32_t* neighbors, size_t degree);
  bool find(uint32_t v, const std::vector<uint32_t>& neighbors, uint64_t h, double& value) const;
  void insert(uint32_t v, const std::vector<uint32_t>& neighbors, uint64_t h, double value);

  size_t max_stars_, stars_ = 0;
  // Per star, one record: centre, degree, the term (two words), the neighbours.
  std::vector<uint32_t> records_;
  // Open addressing: the hash's high half, then the record's offset + 1 (0: empty).
  std::vector<uint64_t> slots_;
};

}  // namespace hodt
