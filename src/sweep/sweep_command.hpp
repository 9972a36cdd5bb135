#pragma once
// `orogen sweep SWEEP.toml --out DIR`: runs every combination of a sweep file's matrix (see
// sweep_plan.hpp) as its own `orogen run` child process, several at once, into DIR/runs/NAME;
// optionally renders each; and tabulates the runs' summaries in DIR/results.csv and .md.
// Started again, it does only what is left: finished runs are skipped, killed ones continued
// from their checkpoint (docs/sweeps.md).
#include <filesystem>

namespace orogen {

struct SweepOptions {
  std::filesystem::path file;  // the sweep file
  std::filesystem::path out;   // the sweep folder
  int jobs = 0;                // runs at once; 0: hardware threads / threads
  int threads = 1;             // OpenMP threads of each run (matters from 16384 discs up)
  bool render = false;         // `orogen render` each finished run (horizons, max_rel_disp)
  bool dry_run = false;        // check everything, list the runs and what each needs; write nothing
};

// Exit codes: 0 every run finished (and was rendered), 1 a run or a render failed (the others
// still ran), 2 bad input (sweep file, a run's configuration, a folder of another sweep),
// nothing started.
int sweep_command(const SweepOptions& options);

}  // namespace orogen
