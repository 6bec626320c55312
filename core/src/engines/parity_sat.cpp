#include "engines/parity_sat.hpp"

namespace hodt {

ParitySat::ParitySat(uint32_t num_vars) : constant_(num_vars), parent_(num_vars + 1), parity_(num_vars + 1, 0) {
  for (uint32_t v = 0; v <= num_vars; ++v) parent_[v] = v;
}

std::pair<uint32_t, bool> ParitySat::find(uint32_t v) {
  // Path halving, the parities composed along the way.
  bool to_root = false;
  uint32_t u = v;
  while (parent_[u] != u) {
    const uint32_t p = parent_[u];
    if (parent_[p] != p) {  // skip p: u's parity to p's parent
      parity_[u] ^= parity_[p];
      parent_[u] = parent_[p];
    }
    to_root ^= parity_[u] != 0;
    u = parent_[u];
  }
  return {u, to_root};
}

void ParitySat::relate(uint32_t v, uint32_t w, bool differ) {
  const auto [rv, pv] = find(v);
  const auto [rw, pw] = find(w);
  if (rv == rw) {
    if ((pv != pw) != differ) contradiction_ = true;
    return;
  }
  // Attach one root under the other; the constant stays a root (it is never
  // attached), so every variable's value is its parity to its root: a free root
  // takes 0, like the constant.
  const bool p = pv != pw ? !differ : differ;  // x_rv xor x_rw
  if (rv == constant_) parent_[rw] = rv, parity_[rw] = p;
  else parent_[rv] = rw, parity_[rv] = p;
}

std::optional<std::vector<uint8_t>> ParitySat::solve() {
  if (contradiction_) return std::nullopt;
  std::vector<uint8_t> x(constant_);
  for (uint32_t v = 0; v < constant_; ++v) x[v] = find(v).second;
  return x;
}

}  // namespace hodt
