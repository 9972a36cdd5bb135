#pragma once
// The set-up of a run (settling the layer, or a branch's replay) in the log and on the
// terminal: a line when it starts and when it ends, the progress line meanwhile, and a log line
// every 30 s; set-ups take seconds at the main job's size and minutes at larger ones.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdint>

#include "run/progress.hpp"
#include "run/status_line_sink.hpp"
#include "util/run_control.hpp"

namespace orogen {

// Reports while it lives (it observes the set-up's loops through util/run_control.hpp).
class SetupReport {
 public:
  SetupReport(spdlog::logger& log, StatusLineSink& line, const Progress& progress, bool branch);
  ~SetupReport();
  SetupReport(const SetupReport&) = delete;
  SetupReport& operator=(const SetupReport&) = delete;

 private:
  void report(std::uint64_t steps, double seconds);

  spdlog::logger& log_;
  StatusLineSink& line_;
  bool show_;
  run_control::ObserverScope observer_;
  std::chrono::steady_clock::time_point start_;
  double next_log_ = 30;
};

}  // namespace orogen
