#include "util/thread_tuner.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>

#include "util/run_control.hpp"

namespace orogen {

ThreadTuner::ThreadTuner(int max_threads, double slice, int probe_every)
    : max_(max_threads), slice_(slice), probe_every_(probe_every), interval_(probe_every), current_(max_threads) {}

void ThreadTuner::restart(double now) {
  slice_start_ = now;
  slice_work_ = 0;
  slice_steps_ = 0;
}

void ThreadTuner::exclude(double seconds) {
  if (slice_start_ >= 0) slice_start_ += seconds;
}

int ThreadTuner::after_step(double work, double now) {
  if (!active()) return current_;
  if (slice_start_ < 0) restart(now);
  slice_work_ += work;
  slice_steps_ += 1;
  const double elapsed = now - slice_start_;
  if (elapsed < slice_) return current_;
  Count& c = stats(current_);
  c.rate = slice_work_ / elapsed;
  c.steps += slice_steps_;
  c.work += slice_work_;
  c.seconds += elapsed;
  restart(now);
  const Count& o = stats(other(current_));
  if (probing_ || o.rate == 0) {
    // After a probe (or before the other count was ever timed): stay on the faster. A probe
    // that confirms the choice makes the next one wait twice as long.
    const bool was_probe = probing_ && o.rate > 0;
    probing_ = o.rate == 0;
    if (o.rate > c.rate || o.rate == 0) {
      current_ = other(current_);
      if (was_probe) interval_ = std::min(2 * interval_, kMaxProbeEvery);
    } else if (was_probe) {
      interval_ = probe_every_;  // the probed count was faster: the machine changed
    }
    slices_since_probe_ = 0;
  } else if (++slices_since_probe_ >= interval_) {
    probing_ = true;
    current_ = other(current_);
  }
  return current_;
}

double ThreadTuner::share(int threads) const {
  const double steps = one_.steps + all_.steps;
  return steps > 0 ? stats(threads).steps / steps : 0.0;
}

namespace {
// Puts the team size asked for back when it goes out of scope.
class TeamSizeGuard {
 public:
  TeamSizeGuard() : threads_(omp_get_max_threads()) {}
  ~TeamSizeGuard() { omp_set_num_threads(threads_); }
  TeamSizeGuard(const TeamSizeGuard&) = delete;
  TeamSizeGuard& operator=(const TeamSizeGuard&) = delete;
  int threads() const { return threads_; }

 private:
  int threads_;
};
}  // namespace

void step_with_tuning(bool adapt, double slice, const std::function<bool()>& step,
                      const std::function<double()>& work) {
  const TeamSizeGuard guard;
  ThreadTuner tuner(adapt ? guard.threads() : 1, slice);
  const auto t0 = std::chrono::steady_clock::now();
  for (std::uint64_t steps = 1; step(); ++steps) {
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run_control::between_steps(steps, now);  // a stop asked for (SIGINT, SIGTERM), progress
    const int threads = tuner.threads();
    if (tuner.after_step(work(), now) != threads) omp_set_num_threads(tuner.threads());
  }
}

std::string ThreadTuner::summary() const {
  if (!active()) return "";
  std::string out;
  for (const int threads : {max_, 1}) {
    const Count& c = stats(threads);
    if (c.steps == 0) continue;
    out += fmt::format("{}{} thread(s) for {:.0f}% of the timed steps ({:.3g} M particle-steps/s)",
                       out.empty() ? "" : ", ", threads, 100 * share(threads), c.work / c.seconds / 1e6);
  }
  return out;
}

}  // namespace orogen
