#pragma once
// The run log's terminal sink, with a status line (the progress line) kept below the log:
// before a log line is written the status line is erased, and it is drawn again under the
// log line, so the two never run into each other. The one place that writes terminal
// control codes; spdlog's sink mutex orders log lines and redraws from any thread.
#include <spdlog/sinks/base_sink.h>

#include <cstdio>
#include <mutex>
#include <string>

namespace orogen {

class StatusLineSink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  explicit StatusLineSink(std::FILE* out = stderr) : out_(out) {}
  // Draws `line` as the status line, replacing the one shown.
  void show(const std::string& line);
  // Leaves the status line shown as it is and moves below it: later log lines start under it.
  void close();

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override;
  void flush_() override;

 private:
  void erase_line();  // with the mutex held
  void draw_line();   // with the mutex held
  std::FILE* out_;
  std::string line_;
  bool shown_ = false;
};

}  // namespace orogen
