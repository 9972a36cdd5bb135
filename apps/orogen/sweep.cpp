// `orogen sweep FILE --out DIR`: a matrix of runs, several at once (src/sweep).
#include <memory>
#include <string>

#include "subcommand.hpp"
#include "sweep/sweep_command.hpp"
#include "config/schema.hpp"

namespace orogen::cli {

Subcommand add_sweep(CLI::App& parent) {
  struct Options {
    SweepOptions sweep;
    std::string file, out;
  };
  auto o = std::make_shared<Options>();
  SweepOptions& sweep = o->sweep;
  auto* cmd = parent.add_subcommand("sweep", "run every combination of a sweep file's matrix, several at once, "
                                             "and tabulate the results (resumable)");
  cmd->add_option("file", o->file, "sweep file (TOML, see docs/sweeps.md)")->required();
  cmd->add_option("--out,-o", o->out, "sweep folder: runs/, logs/, results.csv, results.md")->required();
  cmd->add_option("--jobs,-j", sweep.jobs, "runs at once (default: hardware threads / --threads)")
      ->check(not_empty())
      ->check(count_in(1, 4096));
  cmd->add_option("--threads", sweep.threads, "threads of each run (more only helps from 16384 discs up)")
      ->capture_default_str()
      ->check(not_empty())
      ->check(count_in(1, kMaxThreads));
  cmd->add_flag("--render", sweep.render, "render each finished run (horizons and max_rel_disp)");
  cmd->add_flag("--dry-run", sweep.dry_run, "check the sweep, list its runs and what each needs; run nothing");
  return {cmd, [o] {
            o->sweep.file = o->file;
            o->sweep.out = o->out;
            return sweep_command(o->sweep);
          }};
}

}  // namespace orogen::cli
