// The CLI's progress on stderr: what it is doing, in the phases' names
// (progress.hpp: reading, triangulating, finding the regions, solving exactly,
// ..., writing), how far the phase is and, where the phase knows its size, the
// time left. On a terminal it appears once a run has taken a second and is
// redrawn in place; `--progress` shows it from the start, and as plain lines
// (one at each new phase, else at most one a second) when stderr is not a
// terminal. Everything is decided here, so both CLIs print the same.
#pragma once
#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "hodt/progress.hpp"

namespace hodt {

class CliProgress {
 public:
  using Show = std::function<void(const std::string& text)>;
  // show empty: no progress at all. forced: --progress.
  CliProgress(Show show, bool terminal, bool forced);
  ~CliProgress();  // clears the line it drew (also when the run fails)
  CliProgress(const CliProgress&) = delete;
  CliProgress& operator=(const CliProgress&) = delete;

  // A step of the front end's own, e.g. (Phase::Reading, "points.csv").
  void step(Phase phase, const std::string& what);
  // The solve begins; its phases are shown with what it solves, e.g.
  // "min-local-minima, order 4".
  void solving(const std::string& what);
  // SolveOptions::progress for the solve: empty when nothing would be shown.
  Progress solve_progress();
  // One point of the solve; never cancels.
  bool tick(const ProgressPoint& point);
  // Clears the terminal line it drew, for other text (the input's notes).
  void clear_line();

  // The text after "hodt: " for a point of the solve of `what`.
  static std::string line(const ProgressPoint& point, const std::string& what);

 private:
  using Clock = std::chrono::steady_clock;
  void draw(const std::string& line);
  bool shown() const { return show_ && (forced_ || terminal_); }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  Show show_;
  bool terminal_, forced_;
  Clock::time_point start_ = Clock::now();
  double last_draw_ = -1e9;  // seconds since the start
  std::string solving_;      // what the solve solves
  std::optional<Phase> phase_;  // of the last line drawn
  bool drawn_ = false;  // a terminal line is on screen
};

}  // namespace hodt
