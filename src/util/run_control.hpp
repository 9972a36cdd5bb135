#pragma once
// What the run driver asks of the loops it does not own (the set-up's settling, inside the
// experiments): to stop when SIGINT or SIGTERM asked for it, and to say now and then how far
// they are. The driver's signal handlers record the signal here (src/run/stop_signals.cpp);
// the loops call between_steps() after each step.
#include <cstdint>
#include <functional>
#include <stdexcept>

namespace orogen::run_control {

// Thrown by between_steps() once a stop was asked for: the loop's work is abandoned.
struct Stopped : std::runtime_error {
  explicit Stopped(int sig) : std::runtime_error("stopped by a signal"), signal(sig) {}
  int signal;
};

void record_stop(int signal) noexcept;  // async-signal-safe: called by the signal handlers
int stop_signal() noexcept;             // the signal recorded, or 0
void clear_stop() noexcept;

// Called about once a second by between_steps() with the loop's steps and seconds so far.
using Observer = std::function<void(std::uint64_t steps, double seconds)>;

// Installs an observer while it lives (the previous one comes back after).
class ObserverScope {
 public:
  explicit ObserverScope(Observer fn);
  ~ObserverScope();
  ObserverScope(const ObserverScope&) = delete;
  ObserverScope& operator=(const ObserverScope&) = delete;

 private:
  Observer previous_;
};

// After each step of such a loop: throws Stopped when a stop was asked for, calls the observer
// when a second has passed since its last call.
void between_steps(std::uint64_t steps, double seconds);

}  // namespace orogen::run_control
