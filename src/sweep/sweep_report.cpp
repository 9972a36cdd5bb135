#include "sweep/sweep_report.hpp"
#include "util/timestamp.hpp"

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>

namespace orogen {
namespace {

std::size_t terminal_width() {
  winsize w{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 10) return w.ws_col;
  return 100;
}

}  // namespace

SweepReport::SweepReport(std::filesystem::path log_file)
    : log_file_(std::move(log_file)), tty_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

SweepReport::~SweepReport() { finish(); }

void SweepReport::clear_line() {
  if (drawn_) std::fputs("\r\033[K", stderr);
  drawn_ = false;
}

void SweepReport::event(const std::string& line) {
  clear_line();
  std::fprintf(stderr, "sweep: %s\n", line.c_str());
  std::fflush(stderr);
  // Reopened per line: events are few, and every line is on disk if the sweep is killed.
  std::ofstream(log_file_, std::ios::app) << "[" << local_timestamp() << "] " << line << "\n";
  // The progress line comes back with the next progress() call, up to date.
}

void SweepReport::progress(std::size_t done, std::size_t total, std::size_t failed,
                           const std::vector<std::string>& running, bool force) {
  if (!tty_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_draw_ < std::chrono::milliseconds(250)) return;
  last_draw_ = now;
  const auto secs = std::chrono::duration_cast<std::chrono::seconds>(now - start_).count();
  std::string line = fmt::format(" sweep {}/{} done", done, total);
  if (failed) line += fmt::format(", {} failed", failed);
  line += fmt::format("  {}:{:02d}:{:02d}", secs / 3600, secs / 60 % 60, secs % 60);
  if (!running.empty()) {
    line += fmt::format("  running {}:", running.size());
    for (const auto& r : running) line += " " + r;
  }
  const std::size_t width = terminal_width() - 1;
  if (line.size() > width) line = line.substr(0, width - 3) + "...";
  clear_line();
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
  drawn_ = true;
}

void SweepReport::finish() {
  clear_line();
  std::fflush(stderr);
}

}  // namespace orogen
