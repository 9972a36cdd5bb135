// `orogen charts DIR [--out OUTDIR]`: the charts of a folder (src/commands/charts_command, orogen.charts).
#include <memory>
#include <string>

#include "commands/charts_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_charts(CLI::App& parent) {
  struct Options {
    std::string dir, out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = parent.add_subcommand("charts", "draw the charts of a run, sweep or ensemble folder, chosen by "
                                              "what it holds (python3 -m orogen.charts; docs/python.md)");
  cmd->add_option("dir", o->dir, "a run, sweep or ensemble folder")->required();
  cmd->add_option("--out,-o", o->out, "folder for the charts (default DIR/charts)");
  return {cmd, [o] { return charts_command({o->dir, o->out}); }};
}

}  // namespace orogen::cli
