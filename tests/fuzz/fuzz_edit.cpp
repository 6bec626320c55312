// Live edits against rebuilding: adds, moves and removes from the input on a
// small terrain; after each edit the terrain equals one built from the edited
// points (same triangles), and a refused edit changes nothing.
#include <cstdio>

#include "hodt/error.hpp"
#include "hodt/terrain.hpp"
#include "fuzz_input.hpp"
#include "input_triangles.hpp"

using namespace hodt;

using test::triangles_in_input;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::Bytes in{data, size};
  const uint32_t n = 3 + in.byte() % 10;
  std::vector<double> xyz = fuzz::points(in, n);
  Terrain t;
  try {
    t = Terrain::from_points(xyz);
  } catch (const InputError&) {
    return 0;
  }
  for (int step = 0; step < 12 && in.at < in.size; ++step) {
    const uint8_t op = in.byte() % 3;
    const uint32_t count = static_cast<uint32_t>(xyz.size() / 3);
    const uint32_t i = in.byte() % (count + 1);  // one past the end: refused
    std::vector<double> p = fuzz::points(in, 1);
    std::vector<double> next = xyz;
    const auto before = triangles_in_input(t);
    try {
      if (op == 0) t.add_point(p[0], p[1], p[2]), next.insert(next.end(), p.begin(), p.end());
      else if (op == 1) t.move_point(i, p[0], p[1], p[2]), std::copy(p.begin(), p.end(), next.begin() + 3 * i);
      else t.remove_point(i), next.erase(next.begin() + 3 * i, next.begin() + 3 * i + 3);
    } catch (const InputError&) {
      if (triangles_in_input(t) != before) {
        std::fprintf(stderr, "fuzz_edit: a refused edit changed the terrain\n");
        __builtin_trap();
      }
      continue;
    }
    xyz = next;
    const Terrain fresh = Terrain::from_points(xyz);  // (an edit the terrain took must be a valid terrain)
    if (triangles_in_input(t) != triangles_in_input(fresh)) {
      std::fprintf(stderr, "fuzz_edit: edit %d (op %d) differs from a rebuild\n", step, op);
      __builtin_trap();
    }
  }
  return 0;
}
