#include "hodt/progress.hpp"

#include <chrono>
#include <memory>

namespace hodt {

Progress paced(Progress progress, double interval_ms) {
  if (!progress) return progress;
  using Clock = std::chrono::steady_clock;
  struct State {
    bool started = false;
    double done = 0, total = 0;  // of the last call, passed on or not
    Clock::time_point last;      // of the last call passed on
  };
  // Shared: copies of the returned function (DpLimits are copied) pace together.
  auto state = std::make_shared<State>();
  const auto interval = std::chrono::duration<double, std::milli>(interval_ms);
  return [progress = std::move(progress), state, interval](double done, double total) {
    State& s = *state;
    const bool new_phase = !s.started || total != s.total || done < s.done;
    s.done = done, s.total = total;
    const Clock::time_point now = Clock::now();
    if (!new_phase && now - s.last < interval) return true;
    s.started = true;
    s.last = now;
    return progress(done, total);
  };
}

}  // namespace hodt
