#pragma once
// A one-line progress report on a terminal (step, model time, particle-steps per second,
// time left), redrawn at most a few times a second as the status line of the log's terminal
// sink (so log lines never run into it); silent when stderr is not a terminal.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "run/status_line_sink.hpp"

namespace orogen {

class Progress {
 public:
  enum class Mode { Auto, Always, Never };
  Progress(Mode mode, std::shared_ptr<StatusLineSink> line);
  // fraction < 0: unknown, no time-left estimate.
  void update(std::uint64_t step, double time, std::size_t particles, double fraction, const std::string& status);
  void finish();
  // Whether a line is drawn at all (callers can skip composing its status otherwise).
  bool enabled() const { return enabled_; }
  // Particle-steps per second since the start.
  double rate() const;

 private:
  bool enabled_;
  std::shared_ptr<StatusLineSink> line_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::uint64_t start_step_ = 0;
  bool started_ = false;
  double particle_steps_ = 0;
  std::uint64_t last_step_ = 0;
};

}  // namespace orogen
