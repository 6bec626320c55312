// The engines' one greedy planner: the queue hands out the live variable of
// least current criterion, ties to the lowest index, whatever the history of
// offers; checked against a scan over every variable's latest offer.
#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "engines/elimination_queue.hpp"

using namespace hodt;

namespace {

// The reference: the least (criterion, index) among offered, live variables.
template <class C>
uint32_t least(const std::vector<std::pair<bool, C>>& latest, const std::vector<uint8_t>& gone) {
  uint32_t best = UINT32_MAX;
  for (uint32_t v = 0; v < latest.size(); ++v)
    if (latest[v].first && !gone[v] && (best == UINT32_MAX || latest[v].second < latest[best].second)) best = v;
  return best;
}

}  // namespace

TEST_CASE("elimination queue: the least current criterion, ties to the lowest index, after any offers") {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 400; ++trial) {
    const uint32_t n = 1 + rng() % 40;
    const uint32_t range = 1 + rng() % 6;  // few values: many ties and repeated offers
    EliminationQueue<std::pair<uint32_t, uint32_t>> queue(n);
    std::vector<std::pair<bool, std::pair<uint32_t, uint32_t>>> latest(n, {false, {0, 0}});
    std::vector<uint8_t> gone(n, 0);
    auto offer = [&](uint32_t v) {
      const std::pair<uint32_t, uint32_t> c{rng() % range, rng() % range};
      queue.offer(v, c);
      if (!gone[v]) latest[v] = {true, c};
    };
    for (uint32_t v = 0; v < n; ++v)
      if (rng() % 4) offer(v);
    for (;;) {
      // A step re-offers a few variables, eliminated ones included (ignored).
      for (uint32_t i = rng() % 4; i > 0; --i) offer(rng() % n);
      const uint32_t expected = least(latest, gone);
      const uint32_t v = queue.next();
      REQUIRE(v == expected);
      if (v == UINT32_MAX) break;
      CHECK(queue.eliminated(v));
      gone[v] = 1;
    }
  }
}
