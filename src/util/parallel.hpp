#pragma once
// Below this many discs (or items) a loop runs on one thread: waking a thread team then costs
// more than it saves (on 2 cores: 1.15x from two threads at 1000 discs, 1.45x at 2000 and
// 5000), and on a busy machine a spinning team can be many times slower than one thread (the
// run's thread tuner then falls back to one). Results do not depend on it (every parallel loop is order-free or sums in a fixed
// order), which the determinism tests check by lowering it.
#include <cstddef>
#include <string>

namespace orogen {
constexpr std::ptrdiff_t kMinParallelItems = 2048;
// The largest OROGEN_MIN_PARALLEL_ITEMS accepted (more than any run's discs: all on one thread).
constexpr std::ptrdiff_t kMaxParallelItems = 1000000000;

// kMinParallelItems, or the environment variable OROGEN_MIN_PARALLEL_ITEMS (a whole number
// from 1 to kMaxParallelItems) when set: the tests lower it to take the parallel paths on small runs.
std::ptrdiff_t min_parallel_items();

// What is wrong with OROGEN_MIN_PARALLEL_ITEMS (naming the value and what is allowed), or ""
// when it is unset or valid. The program checks it at start; min_parallel_items() falls
// back to kMinParallelItems for a bad value.
std::string parallel_environment_error();

// The calling thread's static share of the items [0, n) in an OpenMP team: contiguous, in
// thread order (all of them outside a team).
struct ItemRange {
  std::ptrdiff_t begin, end;
};
ItemRange thread_share(std::ptrdiff_t n);
}  // namespace orogen
