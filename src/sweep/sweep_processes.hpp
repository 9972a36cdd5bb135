#pragma once
// Child processes of `orogen sweep`: each run (and each render) is the same executable started
// again with its own arguments, its stdout and stderr appended to a log file, stdin empty.
// A child dies with the sweep (Linux parent-death signal), so a killed sweep leaves no run
// writing behind its back that a restarted sweep could collide with.
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace orogen {

// Starts `orogen ARGS...` (this very executable, /proc/self/exe) with its output appended to
// `log`. Throws std::runtime_error when it cannot start.
pid_t spawn_self(const std::vector<std::string>& args, const std::filesystem::path& log);

struct ChildExit {
  pid_t pid;
  int status;  // the exit status, or 128 + the signal that killed it (as shells report it)
};

// Collects one finished child of this process; nullopt if none has finished (or none is left).
std::optional<ChildExit> reap_child();

}  // namespace orogen
