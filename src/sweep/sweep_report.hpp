#pragma once
// What `orogen sweep` tells the user: one line per event (a run started, skipped, ended) on
// stderr and appended to the sweep's own log, and on a terminal a progress line below them
// (runs done of all, failed, which are running, time so far); no progress line otherwise.
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace orogen {

class SweepReport {
 public:
  explicit SweepReport(std::filesystem::path log_file);
  ~SweepReport();
  SweepReport(const SweepReport&) = delete;
  SweepReport& operator=(const SweepReport&) = delete;

  void event(const std::string& line);
  // Redraws the progress line (at most a few times a second unless `force`).
  void progress(std::size_t done, std::size_t total, std::size_t failed, const std::vector<std::string>& running,
                bool force = false);
  // Ends the progress line.
  void finish();

 private:
  void clear_line();

  std::filesystem::path log_file_;
  bool tty_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace orogen
