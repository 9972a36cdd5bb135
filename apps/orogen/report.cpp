// `orogen report DIR [--out SITE]`: the results atlas (src/commands/report_command, orogen.atlas).
#include <memory>
#include <string>

#include "commands/report_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_report(CLI::App& parent) {
  struct Options {
    std::string dir, out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = parent.add_subcommand("report", "build or update the results atlas: a static web site of every "
                                              "run, sweep and ensemble under DIR (docs/atlas.md)");
  cmd->add_option("dir", o->dir, "folder holding runs, sweeps and ensembles (searched at any depth)")->required();
  cmd->add_option("--out,-o", o->out, "site folder (default DIR/atlas); open SITE/index.html");
  return {cmd, [o] { return report_command({o->dir, o->out}); }};
}

}  // namespace orogen::cli
