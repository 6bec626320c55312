// Progress of long runs, and cancellation through it. Solvers call progress at
// many points of their loops (never more than a few milliseconds of work apart,
// so that a caller can cancel promptly); paced() passes only some of those calls
// on, so that a slow callback (JavaScript, a message to a page) costs nothing.
#pragma once
#include <functional>

#include "hodt/error.hpp"

namespace hodt {

// Called with (done, total) work units of the current phase; return false to
// cancel (the run then throws Cancelled). Phases restart the count.
using Progress = std::function<bool(double done, double total)>;

// Default shortest time between two calls that paced() passes on.
constexpr double kProgressIntervalMs = 5;

// progress, called on the first call, when a phase begins (total changes or done
// goes back) and otherwise at most every interval_ms. Empty if progress is.
Progress paced(Progress progress, double interval_ms = kProgressIntervalMs);

// One progress point: throws Cancelled if the callback says stop.
inline void report(const Progress& progress, double done, double total) {
  if (progress && !progress(done, total)) throw Cancelled();
}

// Paces progress points by work: tick(units) is true once `every` units of work
// have passed since it last was (a unit is an elementary step: a table entry, a
// predicate test), so a loop reports every few dozen microseconds, whatever
// its steps cost.
struct WorkCounter {
  double every = 16384;
  double pending = 0;
  bool tick(double units = 1) {
    if ((pending += units) < every) return false;
    pending = 0;
    return true;
  }
};

}  // namespace hodt
