#pragma once
// `orogen run`: runs an experiment from a configuration, writing outputs, checkpoints and a
// log into one folder, and continues a killed run from its last checkpoint (--resume).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "surface/surface_spec.hpp"

namespace orogen {

struct World;
class Experiment;
class Config;
class MpiSession;

// A rule called between steps (the Python package's hooks, python/orogen): it may read and
// change the world through its API; returning true stops the run like SIGTERM, with a checkpoint.
// The Config is the run's resolved configuration (what config.toml holds).
using BetweenSteps = std::function<bool(World&, const Experiment&, const Config&)>;

// A function that builds on the world of a run that starts from its set-up (the Python
// package's `setup`, the geometry of a scripted experiment): called once after the
// experiment's setup and before output 0. Never on a resume from a checkpoint (that holds what
// it built) nor for a branch (its state is the source's).
using BeforeFirstOutput = std::function<void(World&, const Experiment&, const Config&)>;

struct RunOptions {
  std::optional<std::filesystem::path> config;  // none: the built-in default
  std::vector<std::string> overrides;           // "section.key=value"
  std::filesystem::path out = "out";
  int threads = -1;                             // -1: from the configuration
  bool resume = false;                          // out names a run to continue (overrides: extension keys only)
  std::string from;                             // "RUN_DIR[:OUTPUT]": start from that output (a branch)
  std::int64_t abort_after_outputs = 0;         // test hook: _Exit(137) once this many outputs are written
  BetweenSteps between_steps;                   // none: the CLI's run, untouched
  std::uint64_t between_every = 0;              // called after steps that are multiples of this, before their output
  BeforeFirstOutput before_first_output;        // none: the CLI's run, untouched
  SurfaceScript surface_law;                    // a user's surface law (docs/surface.md); none: the keys' only
  const MpiSession* mpi = nullptr;              // the CLI under mpirun: one run over its ranks (K > 1)
};

// run_command's exit code when between_steps asked the run to stop (it can be resumed).
inline constexpr int kStoppedByHook = 4;

// Exit codes (docs/exit-codes.md, one table for every command): 0 done, 1 I/O (a full or
// read-only disk, a damaged file), 2 bad input (configuration, options, a folder that is not
// this run's or mixes runs), 3 the simulation became unstable, 4 stopped by between_steps,
// 128 + signal when SIGINT or SIGTERM stopped it (with a checkpoint to resume from).
int run_command(const RunOptions& options);

}  // namespace orogen
