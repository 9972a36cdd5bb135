#include "ensemble/ensemble_pool.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "sweep/sweep_processes.hpp"
#include "sweep/sweep_report.hpp"

namespace orogen {

void run_pool(const std::vector<PoolTask>& tasks, std::size_t jobs, SweepReport& report,
              const std::function<void(std::size_t, int)>& on_exit) {
  struct Running {
    pid_t pid;
    std::size_t task;
  };
  std::vector<Running> running;
  std::size_t next = 0, done = 0;
  jobs = std::max<std::size_t>(1, jobs);
  while (next < tasks.size() || !running.empty()) {
    bool changed = false;
    while (running.size() < jobs && next < tasks.size()) {
      const std::size_t k = next++;
      changed = true;
      try {
        running.push_back({spawn_self(tasks[k].args, tasks[k].log), k});
        report.event(tasks[k].name + ": " + tasks[k].what);
      } catch (const std::exception& e) {
        report.event(fmt::format("{}: {}", tasks[k].name, e.what()));
        ++done;
        on_exit(k, 127);
      }
    }
    bool reaped = false;
    while (const auto e = reap_child()) {
      const auto it = std::find_if(running.begin(), running.end(), [&](const Running& r) { return r.pid == e->pid; });
      if (it == running.end()) continue;  // not one of ours
      const std::size_t k = it->task;
      running.erase(it);
      reaped = true;
      ++done;
      on_exit(k, e->status);
    }
    std::vector<std::string> names;
    for (const auto& r : running) names.push_back(tasks[r.task].name);
    report.progress(done, tasks.size(), 0, names, changed || reaped);
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  report.finish();
}

}  // namespace orogen
