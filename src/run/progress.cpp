#include "run/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <utility>

namespace orogen {

Progress::Progress(Mode mode, std::shared_ptr<StatusLineSink> line)
    : enabled_(mode == Mode::Always || (mode == Mode::Auto && isatty(STDERR_FILENO))),
      line_(std::move(line)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double Progress::rate() const {
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return s > 0 ? particle_steps_ / s : 0.0;
}

void Progress::update(std::uint64_t step, double time, std::size_t particles, double fraction,
                      const std::string& status) {
  if (!started_) { started_ = true; start_step_ = step; last_step_ = step; start_ = std::chrono::steady_clock::now(); }
  particle_steps_ += static_cast<double>(step - last_step_) * static_cast<double>(particles);
  last_step_ = step;
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(250)) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::string left = "?";
  if (fraction > 0 && fraction <= 1) {
    const double rest = elapsed / fraction * (1 - fraction);
    left = fmt::format("{:.0f}:{:02.0f}", std::floor(rest / 60), std::fmod(rest, 60.0));
  }
  line_->show(fmt::format(" step {}  t {:.2f}  {:.2f} M particle-steps/s  left {}  {}", step, time, rate() / 1e6,
                          left, status));
}

void Progress::finish() {
  if (enabled_) line_->close();
}

}  // namespace orogen
