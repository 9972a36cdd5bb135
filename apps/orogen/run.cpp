// `orogen run [CONFIG] --out DIR | --resume DIR | --from RUN[:K]`: one run (src/run/runner), as
// one process or, under mpirun, spread over the ranks.
#include <iostream>
#include <memory>
#include <string>

#include "parallel/mpi_session.hpp"
#include "run/runner.hpp"
#include "subcommand.hpp"
#include "config/schema.hpp"

namespace orogen::cli {

Subcommand add_run(CLI::App& parent) {
  struct Options {
    RunOptions run;
    std::string config_path, out = "out", resume_dir;
    CLI::Option* resume = nullptr;
    CLI::Option* from = nullptr;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = parent.add_subcommand("run", "run an experiment (no CONFIG: the built-in default)");
  cmd->add_option("config", o->config_path, "TOML configuration file");
  cmd->add_option("--out,-o", o->out, "output folder")->capture_default_str();
  cmd->add_option("--set", o->run.overrides, "override a key: --set contact.mu=0.2 (repeatable)");
  cmd->add_option("--threads", o->run.threads, "OpenMP threads (default: run.threads, 0 = all cores)")
      ->check(not_empty())
      ->check(count_in(0, kMaxThreads));
  o->resume = cmd->add_option("--resume", o->resume_dir, "continue the killed run in this folder");
  o->from = cmd->add_option("--from", o->run.from,
                            "start from an output of another run: RUN_DIR[:OUTPUT] (default the last), a branch");
  cmd->add_option("--abort-after-outputs", o->run.abort_after_outputs,
                  "test hook: exit 137 with no cleanup once this many outputs are written")
      ->group("");  // hidden
  return {cmd, [o] {
            RunOptions& run = o->run;
            if (!o->config_path.empty()) run.config = o->config_path;
            if (o->resume->count() > 0 && o->resume_dir.empty()) {
              std::cerr << "error: --resume needs a run folder (got an empty one)\n";
              return 2;
            }
            if (o->from->count() > 0 && run.from.empty()) {
              std::cerr << "error: --from needs a run folder (got an empty one)\n";
              return 2;
            }
            if (!o->resume_dir.empty()) {
              run.resume = true;
              run.out = o->resume_dir;
            } else {
              run.out = o->out;
            }
            // Under mpirun every rank runs this one run, each a slab of it (docs/domain-decomposition.md).
            if (MpiSession::launched_without_mpi()) {
              std::cerr << "error: started by mpirun, but this build of orogen has no MPI: each process would run "
                           "the whole run into the same folder; rebuild with MPI installed (OROGEN_MPI=ON), or run "
                           "it without mpirun\n";
              return 2;
            }
            const MpiSession mpi;
            if (mpi.size() > 1) run.mpi = &mpi;
            const int code = run_command(run);
            // A rank that fails alone would leave the others waiting for it: end them all. A stop
            // by a signal or a hook is agreed by every rank, which all end as here.
            if (mpi.size() > 1 && code != 0 && code != kStoppedByHook && code < 128) mpi.abort(code);
            return code;
          }};
}

}  // namespace orogen::cli
