// The thread tuner's choices on a synthetic clock: it times all threads, probes one, keeps the
// faster, and probes again every few slices (less often while the probes confirm the choice),
// so that it follows a machine whose second core comes and goes.
#include <gtest/gtest.h>

#include "util/thread_tuner.hpp"

namespace orogen {
namespace {

// Steps the tuner for `seconds` of wall time at `rate(threads)` particle-steps per second,
// 1000 particle-steps per step; returns the thread count at the end.
template <class Rate>
int step_for(ThreadTuner& t, double& now, double seconds, Rate rate) {
  const double end = now + seconds;
  while (now < end) {
    now += 1000.0 / rate(t.threads());
    t.after_step(1000.0, now);
  }
  return t.threads();
}

TEST(ThreadTuner, KeepsAllThreadsWhenTheyAreFaster) {
  ThreadTuner t(2, 1.0, 4);
  double now = 0;
  auto two_fast = [](int n) { return n == 2 ? 1.5e6 : 1e6; };
  EXPECT_EQ(t.threads(), 2);
  step_for(t, now, 1.01, two_fast);  // first slice on 2, then a probe of 1
  EXPECT_EQ(t.threads(), 1);
  step_for(t, now, 1.01, two_fast);  // the probe was slower: back to 2
  EXPECT_EQ(t.threads(), 2);
  step_for(t, now, 20, two_fast);
  // Mostly on 2: the next probe comes after 8 slices (twice the 4, the first probe having
  // confirmed the choice), the one after that after 16: in 22 slices, 2 probe slices of 1
  // thread (2 x 1000 steps) against 20 of 2 (20 x 1500).
  EXPECT_NEAR(t.share(2), 30000.0 / 32000.0, 0.01);
  const std::string s = t.summary();
  EXPECT_NE(s.find("2 thread(s) for 94%"), std::string::npos) << s;
  EXPECT_NE(s.find("(1.5 M particle-steps/s)"), std::string::npos) << s;
}

TEST(ThreadTuner, FallsBackToOneThreadAndReturnsWhenTheCoreComesBack) {
  ThreadTuner t(2, 1.0, 4);
  double now = 0;
  auto two_slow = [](int n) { return n == 2 ? 0.6e6 : 1e6; };
  step_for(t, now, 2.02, two_slow);
  EXPECT_EQ(t.threads(), 1);
  step_for(t, now, 3.5, two_slow);  // stays on 1 between probes
  EXPECT_EQ(t.threads(), 1);
  step_for(t, now, 10, two_slow);
  EXPECT_GT(t.share(1), 0.8);  // 2 only for its first slice and one probe slice in five
  // The second core is back: the next probe (within five slices) finds two threads faster
  // and keeps them.
  auto two_fast = [](int n) { return n == 2 ? 1.8e6 : 1e6; };
  const double before = t.share(2);
  step_for(t, now, 4.0, two_fast);
  EXPECT_EQ(t.threads(), 2);
  step_for(t, now, 20, two_fast);
  EXPECT_GT(t.share(2), before + 0.3);
}

TEST(ThreadTuner, TimeOutsideSteppingIsNotCounted) {
  ThreadTuner t(2, 1.0, 4);
  t.after_step(1000.0, 0.0);  // the slice starts here
  t.after_step(1000.0, 0.5);
  t.exclude(4.0);  // an output took four seconds (from 0.5 to 4.5): not stepping time
  EXPECT_EQ(t.after_step(1000.0, 4.9), 2);
  EXPECT_EQ(t.summary(), "");  // 0.9 s of stepping: the slice has not ended
  EXPECT_EQ(t.after_step(1000.0, 5.1), 1);  // 1.1 s of stepping: it ends, and one thread is probed
  EXPECT_NE(t.summary().find("(0.00364 M particle-steps/s)"), std::string::npos) << t.summary();  // 4000 / 1.1 s
}

TEST(ThreadTuner, OneThreadIsNotTuned) {
  ThreadTuner t(1, 1.0, 4);
  double now = 0;
  EXPECT_EQ(step_for(t, now, 10, [](int) { return 1e6; }), 1);
  EXPECT_FALSE(t.active());
  EXPECT_EQ(t.summary(), "");
}

}  // namespace
}  // namespace orogen
