#pragma once
// The OpenMP runtime (libgomp) reads its OMP_* and GOMP_* variables when the program loads and
// acts on them at the first parallel region: a thread count of 100000 dies there by SIGSEGV,
// one of 20000 runs on that many threads, and a value it cannot read is ignored after a
// warning. So the variables that steer the engine are checked like configuration keys,
// before anything runs.
#include <string>

namespace orogen {

// What is wrong with the first badly set OMP_NUM_THREADS, OMP_THREAD_LIMIT, OMP_DYNAMIC,
// OMP_NESTED, OMP_WAIT_POLICY, OMP_PROC_BIND, OMP_PLACES, OMP_STACKSIZE, OMP_MAX_ACTIVE_LEVELS,
// OMP_DISPLAY_ENV or GOMP_SPINCOUNT (naming the variable, its value and what is allowed), or ""
// when each is unset or valid. Thread counts may not exceed `max_threads`.
std::string omp_environment_error(int max_threads);

}  // namespace orogen
