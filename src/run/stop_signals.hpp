#pragma once
// SIGINT (Ctrl-C) and SIGTERM ask a run to stop at the end of the current step, with a
// checkpoint, instead of killing it: the handler only records the signal; the run loop asks.
namespace orogen {

// Installs the handlers for the lifetime of the object and restores the old ones after.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal received since installation (SIGINT or SIGTERM), or 0.
  static int received();
};

}  // namespace orogen
