#include "cli/cli_progress.hpp"

#include <algorithm>
#include <cmath>

namespace hodt {
namespace {
constexpr double kQuietSeconds = 1;         // a terminal sees nothing of shorter runs
constexpr double kTerminalRedraw = 0.1;     // seconds between redraws in place
constexpr double kLineInterval = 1;         // seconds between plain progress lines of one phase
constexpr double kPhaseLineInterval = 0.2;  // ... and at least this between those of new phases
const char* const kClearLine = "\r\x1b[K";  // carriage return, erase to the end of the line

std::string about(double seconds) {
  if (seconds < 90) return std::to_string(std::lround(std::max(1.0, seconds))) + " s";
  return std::to_string(std::lround(seconds / 60)) + " min";
}
}  // namespace

CliProgress::CliProgress(Show show, bool terminal, bool forced)
    : show_(std::move(show)), terminal_(terminal), forced_(forced) {}

CliProgress::~CliProgress() { clear_line(); }

void CliProgress::clear_line() {
  if (drawn_) show_(kClearLine);
  drawn_ = false;
}

void CliProgress::draw(const std::string& line) {
  if (!show_) return;
  last_draw_ = seconds();
  if (terminal_) {
    show_(kClearLine + line);
    drawn_ = true;
  } else {
    show_(line + "\n");
  }
}

void CliProgress::step(Phase phase, const std::string& what) {
  phase_ = phase;
  if (forced_ || (terminal_ && seconds() >= kQuietSeconds)) draw("hodt: " + std::string(phase_name(phase)) + " " + what);
}

void CliProgress::solving(const std::string& what) {
  solving_ = what;
  phase_ = Phase::Solving;
  if (forced_ || (terminal_ && seconds() >= kQuietSeconds)) draw("hodt: " + line(ProgressPoint{}, what));
}

Progress CliProgress::solve_progress() {
  if (!shown()) return {};
  return phased([this](const ProgressPoint& p) { return tick(p); });
}

std::string CliProgress::line(const ProgressPoint& p, const std::string& what) {
  std::string text = std::string(phase_name(p.phase)) + " (" + what + ")";
  if (p.sized) {
    text += ": " + std::to_string(static_cast<int>(std::floor(100 * p.fraction))) + "%";
    if (const std::optional<double> left = seconds_left(p)) text += ", about " + about(*left) + " left";
  } else if (p.seconds >= 1) {
    text += ": " + std::to_string(static_cast<long>(p.seconds)) + " s so far";
  }
  return text;
}

bool CliProgress::tick(const ProgressPoint& point) {
  if (!shown()) return true;
  const double now = seconds();
  if (!forced_ && now < kQuietSeconds) return true;
  const bool new_phase = phase_ != point.phase;
  const double interval = terminal_ ? kTerminalRedraw : new_phase ? kPhaseLineInterval : kLineInterval;
  if (!(new_phase && terminal_) && now - last_draw_ < interval) return true;
  phase_ = point.phase;
  draw("hodt: " + line(point, solving_));
  return true;
}

}  // namespace hodt
