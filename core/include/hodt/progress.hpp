// Progress of long runs, and cancellation through it. Solvers call progress at
// many points of their loops (never more than a few milliseconds of work apart,
// so that a caller can cancel promptly) with the (done, total) of whatever loop
// they are in; they do not know what the run as a whole is doing. The drivers
// that start the steps of a run do: they name each step's phase (in_phase), and
// phased() turns the solvers' counts into what a person can read: the phase's
// name, how far it is (a fraction that never goes back within the phase, even
// when the solvers restart their counts) and, where the phase knows its size,
// the time left. It also paces the calls, so that a slow callback (JavaScript, a
// message to a page) costs nothing.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

#include "hodt/error.hpp"

namespace hodt {

// Called with (done, total) work units of the solver's current loop; return
// false to cancel (the run then throws Cancelled). Loops restart the count.
using Progress = std::function<bool(double done, double total)>;

// What a run is doing, in the words of phase_name(). A front end's own steps
// (reading, triangulating, writing) and the solve's: finding the regions of the
// order-k structure, solving exactly (the exact engines, brute force), approximating
// (Baker's scheme), searching (local search, the starts it takes from lower
// orders), proving a bound (the dual bounds of a heuristic answer), measuring
// (the result's value and checks). Solving: work that no driver named.
enum class Phase : uint8_t {
  Reading,
  Triangulating,
  Solving,
  FindingRegions,
  SolvingExactly,
  Approximating,
  Searching,
  ProvingBound,
  Measuring,
  Writing,
};
constexpr size_t kNumPhases = static_cast<size_t>(Phase::Writing) + 1;

// "finding the regions", "solving exactly", ...: the one name of each phase.
std::string_view phase_name(Phase phase);

// One progress point as a person reads it.
struct ProgressPoint {
  Phase phase = Phase::Solving;
  // How far the phase is, in [0, 1]; never less than at the phase's previous
  // point in the same run.
  double fraction = 0;
  // The phase knows its size: fraction is the share of its work done (else it
  // only shows that work goes on, and gives no estimate of the time left).
  bool sized = false;
  double seconds = 0;  // spent in this phase so far
};

// The time the phase still needs, estimated from its pace so far: only for a
// sized phase that has run long enough for its pace to mean something (2 s and
// 5% of its work).
std::optional<double> seconds_left(const ProgressPoint& point);

using PhaseCallback = std::function<bool(const ProgressPoint& point)>;

// Default shortest time between two calls that phased() passes on.
constexpr double kProgressIntervalMs = 5;

// The Progress to give a solve: calls callback at the first point of each phase
// and of each loop of the solvers in it, and otherwise at most every interval_ms
// (0: at every point); callback returning false cancels. Points in no named
// phase come as Phase::Solving.
Progress phased(PhaseCallback callback, double interval_ms = kProgressIntervalMs);

// A plain (done, total) callback as one of phased(): it receives each phase's
// fraction as (fraction, 1). Already phased: progress itself. Empty if progress is.
// (A phased Progress follows one run: its phases' fractions do not restart.)
Progress as_phased(Progress progress, double interval_ms = kProgressIntervalMs);

// progress with the work it is given reported under phase (what a driver passes
// to the solvers of one step). runs: how many counted loops the step's work
// makes, when the driver knows (the phase is then sized: the k-th loop covers
// the k-th of that many equal shares); 0: unknown (each new loop covers a tenth
// of what is left). Unchanged if progress is not phased() or an outer driver holds
// it in a phase (hold_in_phase).
Progress in_phase(const Progress& progress, Phase phase, uint32_t runs = 0);

// The same, and the drivers inside cannot rename it: a whole nested solve
// reported as one phase of the outer run (a lower order solved as a start for
// the search is searching, whatever its own steps are).
Progress hold_in_phase(const Progress& progress, Phase phase, uint32_t runs = 0);

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
