// A spatially coherent order of points (Morton / Z-order of their quantised
// coordinates): vertices numbered this way keep neighbours close in memory, which
// makes every pass over the triangulation cache-friendly on large inputs.
#pragma once
#include <cstdint>
#include <vector>

namespace hodt {

// The permutation: order[k] is the index of the k-th point along the curve.
// Deterministic on every platform (integer keys, ties by x, y, index: equal points
// are consecutive).
std::vector<uint32_t> spatial_order(const std::vector<double>& xyz);

}  // namespace hodt
