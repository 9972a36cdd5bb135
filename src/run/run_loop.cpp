#include "run/run.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <csignal>

#include "run/stop_signals.hpp"
#include "util/thread_tuner.hpp"

namespace fs = std::filesystem;

namespace orogen {

const char* signal_name(int sig) { return sig == SIGINT ? "SIGINT" : "SIGTERM"; }

// Steps to the end, or until SIGINT/SIGTERM: then it checkpoints the step it is at and
// returns the signal (the run resumes from exactly there; no extra output is written, so
// the outputs stay those of an uninterrupted run). Returns 0 when the run finished.
int Run::loop(Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::uint64_t step0 = world_.step();
  double particle_steps = 0;
  auto seconds = [&t0] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  ThreadTuner tuner(settings_.get_bool("run.adapt_threads") ? omp_get_max_threads() : 1,
                    settings_.get_float("run.adapt_slice"));
  while (exp_->advance(world_)) {
    // A scripted rule acts after its step and before that step's output, so outputs show it.
    const bool hook_stop =
        between_every_ > 0 && world_.step() % between_every_ == 0 && between_(world_, *exp_, config_);
    const auto work = static_cast<double>(world_.discs().size());
    particle_steps += work;
    const int threads = tuner.threads();
    if (tuner.after_step(work, seconds()) != threads) omp_set_num_threads(tuner.threads());
    if (world_.time() >= (output_base_ + static_cast<double>(state_.outputs)) * interval_ - 1e-9 * interval_) {
      const double output_start = seconds();
      output();
      const double secs = seconds();
      log().info("output {} at step {} (t = {:.4g}): {} discs, {:.3g} M particle-steps/s{}, {}", state_.outputs - 1,
                 world_.step(), world_.time(), world_.discs().size(), particle_steps / secs / 1e6,
                 tuner.active() ? fmt::format(" (now on {} thread(s))", tuner.threads()) : "", exp_->status(world_));
      if (checkpoint_every_ > 0 && state_.outputs % checkpoint_every_ == 0) checkpoint();
      tuner.exclude(seconds() - output_start);  // outputs are not stepping
    }
    if ((world_.step() & 63) == 0 && progress.enabled())
      progress.update(world_.step(), world_.time(), world_.discs().size(), exp_->fraction_done(world_), exp_->status(world_));
    if (hook_stop) {
      progress.finish();
      checkpoint();
      log().info("stopped by the between-steps hook at step {} (t = {:.6g}) after output {}, with a checkpoint",
                 world_.step(), world_.time(), state_.outputs - 1);
      return -1;
    }
    if (const int sig = stop_signal(); sig != 0) {
      progress.finish();
      checkpoint();
      log().info("stopped by {} at step {} (t = {:.6g}) after output {}, with a checkpoint; continue with orogen run "
                 "--resume {}",
                 signal_name(sig), world_.step(), world_.time(), state_.outputs - 1, dir_.string());
      return sig;
    }
  }
  progress.finish();
  if (state_.output_times.empty() || world_.step() != last_output_step_) output();
  world_.make_whole();
  if (writes_files()) {
    exp_->finish(world_, dir_);
    write_summary();
    for (const auto& observer : observers_) observer(state_.outputs, true);  // e.g. the outputs since the last analysis.every
  }
  state_.finished = true;
  checkpoint();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  log().info("finished at step {} (t = {:.6g}) after {} steps in {:.1f} s ({:.3g} M particle-steps/s, {} neighbour "
             "list builds in all)",
             world_.step(), world_.time(), world_.step() - step0, secs, particle_steps / std::max(secs, 1e-9) / 1e6,
             world_.neighbors().builds);
  if (const auto threads = tuner.summary(); !threads.empty()) log().info("threads: {}", threads);
  return 0;
}

int Run::stop_signal() const {
  if (!max_over_ranks_) return StopSignals::received();
  if ((world_.step() & 63) != 0) return 0;
  return static_cast<int>(max_over_ranks_(StopSignals::received()));
}

void Run::as_rank(int rank, std::function<double(double)> max_over_ranks) {
  rank_ = rank;
  max_over_ranks_ = std::move(max_over_ranks);
}

void Run::between_steps(BetweenSteps fn, std::uint64_t every) {
  between_ = std::move(fn);
  between_every_ = between_ ? every : 0;
}

}  // namespace orogen
