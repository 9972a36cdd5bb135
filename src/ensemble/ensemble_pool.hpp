#pragma once
// A pool of child processes for `orogen ensemble`: each task is this executable started again
// with its own arguments (spawn_self, so it dies with the ensemble), `jobs` at a time, in task
// order. Built on the sweep's process primitives (src/sweep/sweep_processes.hpp,
// sweep_report.hpp).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace orogen {

class SweepReport;

struct PoolTask {
  std::string name;                // for the event lines
  std::vector<std::string> args;   // `orogen ARGS...`
  std::filesystem::path log;       // stdout and stderr appended here
  std::string what;                // "started", "continuing", ...
};

// Runs every task, at most `jobs` at once; calls on_exit(task index, exit status) as each ends
// (status 127 if it could not start; 128 + N if killed by signal N).
void run_pool(const std::vector<PoolTask>& tasks, std::size_t jobs, SweepReport& report,
              const std::function<void(std::size_t, int)>& on_exit);

}  // namespace orogen
