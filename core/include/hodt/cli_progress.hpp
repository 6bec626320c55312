// The CLI's progress on stderr: what it is doing (reading, building, solving,
// writing) and how far the current step is. On a terminal it appears once a run
// has taken a second and is redrawn in place; `--progress` shows it from the
// start, and as plain lines (at most one a second while solving) when stderr is
// not a terminal. Everything is decided here, so both CLIs print the same.
#pragma once
#include <chrono>
#include <functional>
#include <string>

namespace hodt {

class CliProgress {
 public:
  using Show = std::function<void(const std::string& text)>;
  // show empty: no progress at all. forced: --progress.
  CliProgress(Show show, bool terminal, bool forced);
  ~CliProgress();  // clears the line it drew (also when the run fails)
  CliProgress(const CliProgress&) = delete;
  CliProgress& operator=(const CliProgress&) = delete;

  // A new step, e.g. "reading points.csv".
  void step(const std::string& what);
  // SolveOptions::progress: done out of total in the current phase; never cancels.
  bool tick(double done, double total);
  // Clears the terminal line it drew, for other text (the input's notes).
  void clear_line();

 private:
  using Clock = std::chrono::steady_clock;
  void draw(const std::string& line);
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  Show show_;
  bool terminal_, forced_;
  Clock::time_point start_ = Clock::now();
  double last_draw_ = -1e9;  // seconds since the start
  std::string step_;
  bool drawn_ = false;  // a terminal line is on screen
};

}  // namespace hodt
