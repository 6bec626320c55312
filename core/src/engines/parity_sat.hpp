// 2-SAT instances that are parity systems: every constraint x_v = c or
// x_v xor x_w = c. A threshold test of the bottleneck search is one when each
// term over the threshold forbids a state (a forced quad), or both mixed or both
// equal states of two quads: on a raster, whose pairs tie in large groups, every
// term is. Union-find with parity decides it in near-linear time, without the
// implication graph and its strongly connected components.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

namespace hodt {

class ParitySat {
 public:
  explicit ParitySat(uint32_t num_vars);
  // x_v = value.
  void fix(uint32_t v, bool value) { relate(v, constant_, value); }
  // x_v xor x_w = differ.
  void relate(uint32_t v, uint32_t w, bool differ);
  // A solution (each group of variables tied together and to no fixed one
  // takes 0 at its root), or nothing when the constraints contradict each other.
  std::optional<std::vector<uint8_t>> solve();

 private:
  std::pair<uint32_t, bool> find(uint32_t v);  // root, and x_v xor x_root
  uint32_t constant_;                          // a node whose value is 0
  std::vector<uint32_t> parent_;
  std::vector<uint8_t> parity_;                // to the parent
  bool contradiction_ = false;
};

}  // namespace hodt
