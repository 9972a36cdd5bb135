#pragma once
// The tables of a sweep: results.csv (one row per run: its name, the swept values, its exit
// status, then every column of its summary.csv, the union over the runs, empty where a run has
// none, and last the error line of a failed run) and results.md (the same for reading). Both are rewritten atomically whenever a run
// ends, so a long sweep can be looked at while it runs.
#include <filesystem>
#include <optional>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace orogen {

struct SweepOutcome {
  std::optional<int> exit_status;    // of `orogen run`; none: not run (yet)
  std::optional<int> render_status;  // of the renders (first failure); none: not rendered
  std::string error;                 // a failed run or render: the last line of its log
};

// Writes out_dir/results.csv and out_dir/results.md; outcomes[i] belongs to plan.runs[i].
// Summaries are read from out_dir/runs/NAME/summary.csv of the runs that exited 0.
void write_sweep_results(const std::filesystem::path& out_dir, const SweepPlan& plan,
                         const std::vector<SweepOutcome>& outcomes, bool with_render);

}  // namespace orogen
