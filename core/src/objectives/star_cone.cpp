#include "objectives/star_cone.hpp"

#include <algorithm>
#include <utility>

#include "hodt/predicates.hpp"

namespace hodt {

namespace {

// A generator of a cone at v: a vertex w (the vector w - v) or +-e_z.
constexpr uint32_t kUpZ = UINT32_MAX, kDownZ = UINT32_MAX - 1;

// Sign of det[a; b; c] for generators at v, exactly.
int det_sign(const Mesh& m, uint32_t v, uint32_t a, uint32_t b, uint32_t c) {
  const auto vertical = [](uint32_t g) { return g >= kDownZ; };
  const int nz = vertical(a) + vertical(b) + vertical(c);
  if (nz == 0) return orient3d(m.point(v), m.point(a), m.point(b), m.point(c));
  if (nz > 1) return 0;  // two vertical rows
  // Rotate the vertical generator to the last row (cyclic: same sign), then
  // det[x; y; s e_z] = s * ((x - v) cross (y - v)).z = s * orient2d(v, x, y).
  if (vertical(a)) std::swap(a, c), std::swap(a, b);  // (a, b, c) -> (b, c, a): cyclic
  else if (vertical(b)) std::swap(b, c), std::swap(a, b);  // (a, b, c) -> (c, a, b): cyclic
  const int s = c == kUpZ ? 1 : -1;
  return s * orient2d(m.point(v), m.point(a), m.point(b));
}

// The generators at v (vertices, then +e_z and -e_z) and their determinants,
// each computed once.
class Generators {
 public:
  // (fixed and nb disjoint: a repeated vertex would cost exact zero tests)
  Generators(const Mesh& m, uint32_t v, const std::vector<uint32_t>& fixed, const std::vector<uint32_t>& nb)
      : m_(m), v_(v), id_(fixed) {
    id_.insert(id_.end(), nb.begin(), nb.end());
    id_.push_back(kUpZ), id_.push_back(kDownZ);
    n_ = id_.size();
    sign_.assign(n_ * n_ * n_, kUnknown);
  }
  size_t up() const { return n_ - 2; }
  size_t down() const { return n_ - 1; }

  int det(size_t i, size_t j, size_t k) {
    int8_t& s = sign_[(i * n_ + j) * n_ + k];
    if (s == kUnknown) {
      const int d = i == j || j == k || i == k ? 0 : det_sign(m_, v_, id_[i], id_[j], id_[k]);
      // (every even permutation has the same sign, every odd one the opposite)
      sign_[(i * n_ + j) * n_ + k] = sign_[(j * n_ + k) * n_ + i] = sign_[(k * n_ + i) * n_ + j] = static_cast<int8_t>(d);
      sign_[(j * n_ + i) * n_ + k] = sign_[(i * n_ + k) * n_ + j] = sign_[(k * n_ + j) * n_ + i] = static_cast<int8_t>(-d);
    }
    return s;
  }

  // Is generator q in the closed cone of generators `gen`? True only when
  // certified by an independent triple containing it (every point of a
  // full-dimensional cone is in one).
  bool in_cone(const std::vector<size_t>& gen, size_t q) {
    const size_t n = gen.size();
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b)
        for (size_t c = b + 1; c < n; ++c) {
          const size_t i = gen[a], j = gen[b], k = gen[c];
          const int d = det(i, j, k);
          // Cramer: the coefficients of q have the signs of these over d.
          if (d != 0 && det(q, j, k) * d >= 0 && det(i, q, k) * d >= 0 && det(i, j, q) * d >= 0) return true;
        }
    return false;
  }

 private:
  static constexpr int8_t kUnknown = 2;
  const Mesh& m_;
  uint32_t v_;
  std::vector<uint32_t> id_;
  size_t n_;
  std::vector<int8_t> sign_;
};

}  // namespace

void drop_implied_neighbors(const Mesh& m, uint32_t v, const std::vector<uint32_t>& fixed, std::vector<uint32_t>& nb,
                            std::initializer_list<StarSide> sides) {
  const auto mark = [](StarSide side) { return side == StarSide::Below ? kNoPlaneBelow : kNoPlaneAbove; };
  std::vector<uint32_t> marks;
  while (!nb.empty() && nb.back() >= kNoPlaneAbove) marks.push_back(nb.back()), nb.pop_back();
  // The fixed ones will be there anyway.
  nb.erase(std::remove_if(nb.begin(), nb.end(), [&](uint32_t w) { return std::binary_search(fixed.begin(), fixed.end(), w); }),
           nb.end());
  Generators g(m, v, fixed, nb);
  const size_t f = fixed.size(), n = nb.size();  // generator f + i is nb[i]
  std::vector<size_t> all(f + n);
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  std::vector<uint8_t> keep(n, 0), needed(n);
  std::vector<size_t> gen, essential;
  for (const StarSide side : sides) {
    if (std::find(marks.begin(), marks.end(), mark(side)) != marks.end()) continue;
    // No plane on this side (e_z, or -e_z, in the cone of the neighbours): its mark.
    if (g.in_cone(all, side == StarSide::Below ? g.up() : g.down())) {
      marks.push_back(mark(side));
      continue;
    }
    // The essential ones: implied by none of the others (with the fixed ones and
    // the vertical away from the side). Dropping all the rest at once is sound
    // when the essential ones imply each dropped one (always for a polygon with
    // an interior); else the side keeps them all.
    const size_t away = side == StarSide::Below ? g.down() : g.up();
    essential.assign(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(f));
    essential.push_back(away);
    for (size_t i = 0; i < n; ++i) {
      gen = all;
      gen.erase(gen.begin() + static_cast<std::ptrdiff_t>(f + i));
      gen.push_back(away);
      needed[i] = !g.in_cone(gen, f + i);
      if (needed[i]) essential.push_back(f + i);
    }
    bool sound = true;
    for (size_t i = 0; i < n && sound; ++i) sound = needed[i] || g.in_cone(essential, f + i);
    for (size_t i = 0; i < n; ++i) keep[i] |= needed[i] || !sound;
  }
  size_t out = 0;
  for (size_t i = 0; i < n; ++i)
    if (keep[i]) nb[out++] = nb[i];
  nb.resize(out);
  std::sort(marks.begin(), marks.end());
  nb.insert(nb.end(), marks.begin(), marks.end());
}

}  // namespace hodt
