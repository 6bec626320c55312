#include "hodt/cli_progress.hpp"

#include <algorithm>
#include <cmath>

namespace hodt {
namespace {
constexpr double kQuietSeconds = 1;         // a terminal sees nothing of shorter runs
constexpr double kTerminalRedraw = 0.1;     // seconds between redraws in place
constexpr double kLineInterval = 1;         // seconds between plain progress lines
const char* const kClearLine = "\r\x1b[K";  // carriage return, erase to the end of the line
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

void CliProgress::step(const std::string& what) {
  step_ = what;
  if (forced_ || (terminal_ && seconds() >= kQuietSeconds)) draw("hodt: " + step_);
}

bool CliProgress::tick(double done, double total) {
  if (!show_ || (!forced_ && !terminal_)) return true;
  const double now = seconds();
  if (!forced_ && now < kQuietSeconds) return true;
  if (now - last_draw_ < (terminal_ ? kTerminalRedraw : kLineInterval)) return true;
  const double percent = total > 0 ? std::floor(100 * std::min(1.0, done / total)) : 0;
  draw("hodt: " + step_ + ": " + std::to_string(static_cast<int>(percent)) + "% of this phase, " +
       std::to_string(static_cast<long>(now)) + " s");
  return true;
}

}  // namespace hodt
