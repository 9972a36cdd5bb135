#pragma once
// Picks the faster of one thread and all of them while a run steps. On a shared machine a
// second core is at times not a core of its own (two threads then run slower than one, with
// nothing else running here), and the phases come and go during a long run. Results do not
// depend on the thread count (every loop sums in a fixed order), so switching is free.
#include <functional>
#include <string>

namespace orogen {

class ThreadTuner {
 public:
  // max_threads: the team size asked for (1 turns tuning off); slice: wall seconds each
  // count is timed for before the next decision; probe_every: slices on the chosen count
  // between two probes of the other, doubled after each probe that confirms the choice (up
  // to kMaxProbeEvery) and back to probe_every after a switch: a probe runs a slice on the
  // slower count, 4% of the main job's stepping time when every eighth slice was one.
  ThreadTuner(int max_threads, double slice, int probe_every = 8);
  static constexpr int kMaxProbeEvery = 32;

  // The work of one step (particle-steps) done at wall time `now` [s]. Returns the thread
  // count for the next step (changed only at the end of a slice).
  int after_step(double work, double now);
  // Leaves `seconds` of wall time out of the slice under way (work that is not stepping:
  // outputs, checkpoints). The slice keeps its steps, so frequent outputs do not keep it
  // from ever ending.
  void exclude(double seconds);

  int threads() const { return current_; }
  bool active() const { return max_ > 1; }
  // Fraction of the timed steps run on this thread count (1 or max_threads).
  double share(int threads) const;
  // Steps and rates by thread count over the slices timed so far, for the log ("" when not
  // active or before the first slice ends).
  std::string summary() const;

 private:
  struct Count {
    double rate = 0;   // particle-steps per second, last slice timed on this count
    double steps = 0;  // steps run on it
    double work = 0, seconds = 0;
  };
  void restart(double now);
  Count& stats(int threads) { return threads == 1 ? one_ : all_; }
  const Count& stats(int threads) const { return threads == 1 ? one_ : all_; }
  int other(int threads) const { return threads == 1 ? max_ : 1; }

  int max_;
  double slice_;
  int probe_every_;
  int interval_;  // slices between probes now (probe_every_ .. kMaxProbeEvery)
  int current_;
  bool probing_ = false;
  int slices_since_probe_ = 0;
  double slice_start_ = -1, slice_work_ = 0, slice_steps_ = 0;
  Count one_, all_;
};

// Calls `step` until it returns false, switching the OpenMP team size as a ThreadTuner of the
// current size decides (none when `adapt` is false), as the run's main loop does; `work` gives
// a step's particle-steps. For the settling loops of an experiment's set-up, which would
// otherwise spin a whole team on a busy machine. The team size asked for before is restored
// afterwards (also on an exception), so that the main loop tunes from the same start. After
// each step it calls run_control::between_steps: a stop asked for by SIGINT or SIGTERM ends the
// loop with run_control::Stopped, and the run driver hears how far the set-up is.
void step_with_tuning(bool adapt, double slice, const std::function<bool()>& step,
                      const std::function<double()>& work);

}  // namespace orogen
