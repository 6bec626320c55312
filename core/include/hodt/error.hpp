// Errors the library reports to its callers. Every message names what is wrong
// (an index, a line, a value) so that a CLI or a page can show it as is.
#pragma once
#include <stdexcept>
#include <string>

namespace hodt {

// Bad input: malformed file, NaN coordinate, duplicate point, invalid triangulation.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A valid request the library refuses: brute force on too many quads, a tree
// decomposition wider than the memory cap, an objective a method does not support.
struct LimitError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The caller asked to stop (progress callback returned false).
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace hodt
