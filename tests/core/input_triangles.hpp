// A terrain's triangles in input indices, each starting at its smallest index, as
// a set: two terrains of the same points compare equal whatever their internal
// vertex and triangle order (live edits against rebuilding, in tests and fuzzing).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <set>

#include "hodt/terrain.hpp"

namespace hodt::test {

inline std::set<std::array<uint32_t, 3>> triangles_in_input(const Terrain& t) {
  std::set<std::array<uint32_t, 3>> out;
  const Mesh& m = t.structure().base;
  for (uint32_t k = 0; k < m.num_triangles(); ++k) {
    std::array<uint32_t, 3> v = {t.to_input(m.triangles[3 * k]), t.to_input(m.triangles[3 * k + 1]),
                                 t.to_input(m.triangles[3 * k + 2])};
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    out.insert(v);
  }
  return out;
}

}  // namespace hodt::test
