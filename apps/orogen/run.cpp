// `orogen run [CONFIG] --out DIR | --resume DIR | --from RUN[:K]`: one run (src/run/runner).
#include <iostream>
#include <memory>
#include <string>

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
            return run_command(run);
          }};
}

}  // namespace orogen::cli
