#include "run/stop_signals.hpp"

#include <csignal>

#include "util/run_control.hpp"

namespace orogen {
namespace {

struct sigaction g_old_int, g_old_term;

// Recorded where the run loop and the set-up's loops (util/run_control.hpp) both ask.
extern "C" void record_signal(int sig) { run_control::record_stop(sig); }

}  // namespace

StopSignals::StopSignals() {
  run_control::clear_stop();
  struct sigaction action {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // writes in progress finish; the loop checks between steps
  sigaction(SIGINT, &action, &g_old_int);
  sigaction(SIGTERM, &action, &g_old_term);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
  run_control::clear_stop();  // a later loop of this process is not stopped by this run's signal
}

int StopSignals::received() { return run_control::stop_signal(); }

}  // namespace orogen
