// The class of a vertex over its neighbours (measures.hpp), one neighbourhood at
// a time or many of one centre at once (neighbourhood_classes.hpp), through one
// walk over the triangles of neighbours that contain the centre.
#include <vector>

#include "hodt/measures.hpp"
#include "hodt/predicates.hpp"
#include "objectives/neighbourhood_classes.hpp"

namespace hodt {

namespace {

// orient2d(p, nb[i], nb[j]) for all pairs, in o (d x d).
void centre_orientations(const double* p, const double* const* nb, uint32_t d, int8_t* o) {
  for (uint32_t i = 0; i < d; ++i)
    for (uint32_t j = i + 1; j < d; ++j) {
      const int s = orient2d(p, nb[i], nb[j]);
      o[i * d + j] = static_cast<int8_t>(s);
      o[j * d + i] = static_cast<int8_t>(-s);
    }
}

// Every triangle i < j < k of neighbours that contains p in the plane (closed,
// not degenerate), with h = +1 (-1) when p is strictly above (below) its plane,
// 0 on it: visit(i, j, k, h), until it returns false. o: centre_orientations.
template <class Visit>
void containing_triangles(const double* p, const double* const* nb, uint32_t d, const int8_t* o, Visit visit) {
  for (uint32_t i = 0; i < d; ++i)
    for (uint32_t j = i + 1; j < d; ++j)
      for (uint32_t k = j + 1; k < d; ++k) {
        // p in the closed triangle i, j, k of orientation s: orient(i, j, p) =
        // orient(p, i, j) etc. all of sign s or 0. The signs in hand rule out
        // most triples before their own orientation is computed (on a raster,
        // where neighbours lie on common lines, that takes the exact predicate).
        const int a = o[i * d + j], b = o[j * d + k], c = o[k * d + i];
        const bool ccw = a >= 0 && b >= 0 && c >= 0, cw = a <= 0 && b <= 0 && c <= 0;
        if (!ccw && !cw) continue;
        const int s = orient2d(nb[i], nb[j], nb[k]);
        if (s == 0 || (s > 0 && !ccw) || (s < 0 && !cw)) continue;
        if (!visit(i, j, k, orient3d(nb[i], nb[j], nb[k], p) * s)) return;
      }
}

}  // namespace

VertexClass vertex_class(const double* p, const double* const* nb, uint32_t d, bool below_known, bool above_known) {
  // (On the stack for the usual degrees: this runs for every fan a solver weighs.)
  int8_t small[32 * 32];
  std::vector<int8_t> large(d > 32 ? size_t(d) * d : 0);
  int8_t* o = d > 32 ? large.data() : small;
  centre_orientations(p, nb, d, o);
  // Flat: all neighbours on one plane through p.
  uint32_t fi = d, fj = d;
  for (uint32_t i = 0; i < d && fi == d; ++i)
    for (uint32_t j = i + 1; j < d; ++j)
      if (o[i * d + j] != 0) { fi = i, fj = j; break; }
  const bool known = below_known || above_known;  // (then not flat)
  if (fi == d && !known) return kFlat;  // cannot happen for an interior vertex
  bool flat = !known;
  for (uint32_t k = 0; k < d && flat; ++k)  // (k = fi, fj are on the plane: skip the exact zero)
    flat = k == fi || k == fj || orient3d(p, nb[fi], nb[fj], nb[k]) == 0;
  if (flat) return kFlat;
  // p is strictly below (above) the upper (lower) hull of its neighbours iff some
  // triangle of neighbours contains p in the plane and has p strictly below (above) it.
  bool below = below_known, above = above_known;
  if (!(below && above))
    containing_triangles(p, nb, d, o, [&](uint32_t, uint32_t, uint32_t, int h) {
      below = below || h < 0, above = above || h > 0;
      return !(below && above);
    });
  if (below && above) return kMixed;
  return below ? kConcave : kConvex;
}

NeighbourhoodClasses::NeighbourhoodClasses(const double* centre, std::vector<const double*> fixed,
                                           std::vector<const double*> optional)
    : centre_(centre), candidates_(std::move(fixed)), num_fixed_(static_cast<uint32_t>(candidates_.size())) {
  candidates_.insert(candidates_.end(), optional.begin(), optional.end());
  const uint32_t d = static_cast<uint32_t>(candidates_.size());
  direct_ = d > kMaxCandidates || optional.size() > 32;
  if (direct_) return;
  int8_t o[kMaxCandidates * kMaxCandidates];
  centre_orientations(centre, candidates_.data(), d, o);
  containing_triangles(centre, candidates_.data(), d, o, [&](uint32_t i, uint32_t j, uint32_t k, int h) {
    const uint64_t corners = (uint64_t{1} << i) | (uint64_t{1} << j) | (uint64_t{1} << k);
    if (h < 0) below_.push_back(corners);
    if (h > 0) above_.push_back(corners);
    return true;
  });
}

VertexClass NeighbourhoodClasses::of(uint32_t mask) const {
  auto direct = [&] {
    std::vector<const double*> nb(candidates_.begin(), candidates_.begin() + num_fixed_);
    for (uint32_t i = num_fixed_; i < candidates_.size(); ++i)
      if ((mask >> (i - num_fixed_)) & 1) nb.push_back(candidates_[i]);
    return vertex_class(centre_, nb.data(), static_cast<uint32_t>(nb.size()));
  };
  if (direct_) return direct();
  const uint64_t present = ((uint64_t{1} << num_fixed_) - 1) | (uint64_t{mask} << num_fixed_);
  auto held = [&](const std::vector<uint64_t>& witnesses) {
    for (uint64_t corners : witnesses)
      if ((corners & present) == corners) return true;
    return false;
  };
  const bool below = held(below_), above = held(above_);
  if (below && above) return kMixed;
  if (below) return kConcave;
  if (above) return kConvex;
  return direct();  // on both hulls: flat, or convex all the same
}

}  // namespace hodt
