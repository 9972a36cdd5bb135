#include "util/run_control.hpp"

#include <csignal>
#include <utility>

namespace orogen::run_control {
namespace {

volatile std::sig_atomic_t g_signal = 0;
Observer g_observer;
double g_last_report = 0;

}  // namespace

void record_stop(int signal) noexcept { g_signal = signal; }
int stop_signal() noexcept { return g_signal; }
void clear_stop() noexcept { g_signal = 0; }

ObserverScope::ObserverScope(Observer fn) : previous_(std::exchange(g_observer, std::move(fn))) {
  g_last_report = 0;
}
ObserverScope::~ObserverScope() { g_observer = std::move(previous_); }

void between_steps(std::uint64_t steps, double seconds) {
  if (const int sig = g_signal; sig != 0) throw Stopped(sig);
  if (!g_observer) return;
  if (seconds < g_last_report + 1.0 && seconds >= g_last_report) return;
  g_last_report = seconds;
  g_observer(steps, seconds);
}

}  // namespace orogen::run_control
