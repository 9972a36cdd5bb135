#include "run/status_line_sink.hpp"

namespace orogen {
namespace {
// Carriage return, then "erase to the end of the line" (ECMA-48 EL): the cursor is back at
// column 0 on an empty line.
constexpr const char* kEraseLine = "\r\033[K";
}  // namespace

void StatusLineSink::show(const std::string& line) {
  std::lock_guard<std::mutex> lock(mutex_);
  line_ = line;
  erase_line();
  draw_line();
  std::fflush(out_);
}

void StatusLineSink::close() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (shown_) std::fputc('\n', out_);
  shown_ = false;
  line_.clear();
  std::fflush(out_);
}

void StatusLineSink::sink_it_(const spdlog::details::log_msg& msg) {
  spdlog::memory_buf_t text;
  formatter_->format(msg, text);
  erase_line();
  std::fwrite(text.data(), 1, text.size(), out_);
  if (!line_.empty()) draw_line();
  std::fflush(out_);
}

void StatusLineSink::flush_() { std::fflush(out_); }

void StatusLineSink::erase_line() {
  if (shown_) std::fputs(kEraseLine, out_);
  shown_ = false;
}

void StatusLineSink::draw_line() {
  std::fputs(line_.c_str(), out_);
  shown_ = true;
}

}  // namespace orogen
