#pragma once
// `orogen run`: runs an experiment from a configuration, writing outputs, checkpoints and a
// log into one folder, and continues a killed run from its last checkpoint (--resume).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace orogen {

struct RunOptions {
  std::optional<std::filesystem::path> config;  // none: the built-in default
  std::vector<std::string> overrides;           // "section.key=value"
  std::filesystem::path out = "out";
  int threads = -1;                             // -1: from the configuration
  bool resume = false;                          // out names a run to continue (overrides: extension keys only)
  std::string from;                             // "RUN_DIR[:OUTPUT]": start from that output (a branch)
  std::int64_t abort_after_outputs = 0;         // test hook: _Exit(137) once this many outputs are written
};

// Exit codes: 0 done, 1 I/O failure (a full disk, an unwritable file), 2 bad input
// (configuration, folder), 3 the simulation became unstable, 128 + signal when SIGINT or
// SIGTERM stopped it (with a checkpoint to resume from).
int run_command(const RunOptions& options);

}  // namespace orogen
