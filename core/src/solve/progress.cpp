#include "hodt/progress.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>

namespace hodt {

namespace {

constexpr std::array<std::string_view, kNumPhases> kPhaseNames = {
    "reading",         "triangulating", "solving",         "finding the regions", "solving exactly",
    "approximating",   "searching",     "proving a bound", "measuring",           "writing",
};

constexpr double kEstimateAfterSeconds = 2;   // a pace measured over less says little
constexpr double kEstimateAfterFraction = 0.05;
// A phase of unknown size: the share of what is left that each new loop covers.
// Small, so that a phase of many loops (a region engine's can make hundreds)
// still moves late in it, rather than standing at 100% after a dozen.
constexpr double kUnsizedLoopShare = 0.1;

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// The state of one run's phases, shared by every Progress that in_phase() made
// from the one phased() made (the solvers copy them into their limits).
class PhaseTracker {
 public:
  PhaseTracker(PhaseCallback callback, double interval_ms)
      : callback_(std::move(callback)),
        interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::milli>(interval_ms))) {}

  bool point(Phase phase, uint32_t runs, double done, double total) {
    const Clock::time_point now = Clock::now();
    const bool new_phase = !started_ || phase != current_;
    if (new_phase) {
      if (started_) phases_[index(current_)].seconds += seconds_between(entered_, now);
      current_ = phase, entered_ = now, started_ = true;
    }
    State& s = phases_[index(phase)];
    // A new loop: the phase (re)entered, or the solver's count restarted. It
    // covers the next share of the phase, from where the phase is: the fraction
    // can only grow.
    const bool new_loop = new_phase || total != s.last_total || done < s.last_done;
    if (new_loop) {
      ++s.runs;
      s.from = s.fraction;
      if (s.sized && runs > 0 && s.runs <= runs) {
        s.to = std::max(s.fraction, static_cast<double>(s.runs) / runs);
      } else {  // more loops than the driver said, or it did not know
        s.sized = false;
        s.to = s.fraction + (1 - s.fraction) * kUnsizedLoopShare;
      }
    }
    s.last_done = done, s.last_total = total;
    const double share = total > 0 && done > 0 ? std::min(1.0, done / total) : 0;  // (NaN: 0)
    s.fraction = std::max(s.fraction, s.from + (s.to - s.from) * share);
    // (Each new loop is passed on too, as the solvers' phases were before they
    // had names: a caller that cancels from its callback is asked at every step.)
    if (!new_loop && now - last_passed_ < interval_) return true;
    last_passed_ = now;
    return callback_(ProgressPoint{phase, s.fraction, s.sized, s.seconds + seconds_between(entered_, now)});
  }

 private:
  struct State {
    double fraction = 0;
    uint32_t runs = 0;     // loops seen
    bool sized = true;     // until shown otherwise
    double from = 0, to = 0;  // the share of the phase the current loop covers
    double last_done = 0, last_total = 0;
    double seconds = 0;    // in the phase before it was last entered
  };
  static size_t index(Phase p) { return static_cast<size_t>(p); }

  PhaseCallback callback_;
  Clock::duration interval_;
  bool started_ = false;
  Phase current_ = Phase::Solving;
  Clock::time_point entered_, last_passed_;
  std::array<State, kNumPhases> phases_{};
};

// What phased() and in_phase() return; found again in a Progress by its type.
struct PhaseCall {
  std::shared_ptr<PhaseTracker> tracker;
  Phase phase = Phase::Solving;
  uint32_t runs = 0;
  bool held = false;
  bool operator()(double done, double total) const { return tracker->point(phase, runs, done, total); }
};

Progress with_phase(const Progress& progress, Phase phase, uint32_t runs, bool held) {
  const PhaseCall* call = progress.target<PhaseCall>();
  if (!call || call->held) return progress;
  return PhaseCall{call->tracker, phase, runs, held};
}

}  // namespace

std::string_view phase_name(Phase phase) { return kPhaseNames[static_cast<size_t>(phase)]; }

std::optional<double> seconds_left(const ProgressPoint& p) {
  if (!p.sized || p.seconds < kEstimateAfterSeconds || p.fraction < kEstimateAfterFraction || p.fraction >= 1)
    return std::nullopt;
  return p.seconds / p.fraction * (1 - p.fraction);
}

Progress phased(PhaseCallback callback, double interval_ms) {
  if (!callback) return {};
  return PhaseCall{std::make_shared<PhaseTracker>(std::move(callback), interval_ms)};
}

Progress as_phased(Progress progress, double interval_ms) {
  if (!progress || progress.target<PhaseCall>()) return progress;
  return phased([progress = std::move(progress)](const ProgressPoint& p) { return progress(p.fraction, 1); }, interval_ms);
}

Progress in_phase(const Progress& progress, Phase phase, uint32_t runs) { return with_phase(progress, phase, runs, false); }

Progress hold_in_phase(const Progress& progress, Phase phase, uint32_t runs) {
  return with_phase(progress, phase, runs, true);
}

}  // namespace hodt
