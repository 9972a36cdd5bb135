#include "run/setup_report.hpp"

#include <fmt/format.h>

#include <exception>

namespace orogen {

SetupReport::SetupReport(spdlog::logger& log, StatusLineSink& line, const Progress& progress, bool branch)
    : log_(log), line_(line), show_(progress.enabled()),
      observer_([this](std::uint64_t steps, double seconds) { report(steps, seconds); }),
      start_(std::chrono::steady_clock::now()) {
  log_.info("set-up: {}", branch ? "the branch's state (from the source's checkpoint, or a replay of the source)"
                                 : "building the initial state (settling the layer)");
}

SetupReport::~SetupReport() {
  if (show_) line_.close();
  if (std::uncaught_exceptions() == 0)
    log_.info("set-up done in {:.1f} s", std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
}

void SetupReport::report(std::uint64_t steps, double seconds) {
  if (show_) line_.show(fmt::format(" set-up: step {} of this stage, {:.0f} s", steps, seconds));
  if (seconds >= next_log_) {
    log_.info("set-up: step {} of this stage after {:.0f} s", steps, seconds);
    next_log_ = seconds + 30;
  }
}

}  // namespace orogen
