// `orogen ensemble FILE --out DIR`: seeds and variants of a preset and their statistics (src/ensemble).
#include <memory>
#include <string>

#include "ensemble/ensemble_command.hpp"
#include "subcommand.hpp"
#include "config/schema.hpp"

namespace orogen::cli {

Subcommand add_ensemble(CLI::App& parent) {
  struct Options {
    EnsembleOptions ensemble;
    std::string file, out;
  };
  auto o = std::make_shared<Options>();
  EnsembleOptions& ensemble = o->ensemble;
  auto* cmd = parent.add_subcommand("ensemble", "run a preset over seeds and/or variants (in parallel, or "
                                                "under mpirun) and compute their statistics (resumable)");
  cmd->add_option("file", o->file, "ensemble file (TOML, see docs/ensembles.md)")->required();
  cmd->add_option("--out,-o", o->out, "ensemble folder: members/, aggregate/, results.csv, results.md")->required();
  cmd->add_option("--jobs,-j", ensemble.jobs, "members at once (default: the cores, or the members if fewer)")
      ->check(not_empty())
      ->check(count_in(1, 4096));
  cmd->add_option("--threads", ensemble.threads,
                  "threads of each member (default: the cores left over when members are fewer)")
      ->check(not_empty())
      ->check(count_in(1, kMaxThreads));
  cmd->add_flag("--dry-run", ensemble.dry_run, "check the ensemble, list its members; run nothing");
  cmd->add_flag("--no-stats", ensemble.no_stats, "run the members only (python3 -m orogen.stats DIR later)");
  return {cmd, [o] {
            o->ensemble.file = o->file;
            o->ensemble.out = o->out;
            return ensemble_command(o->ensemble);
          }};
}

}  // namespace orogen::cli
