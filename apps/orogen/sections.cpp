// `orogen sections DIR [OPTIONS]`: a wedge run's cross-sections (src/commands/sections_command,
// orogen.charts.sections); the options are the module's, checked there.
#include <memory>
#include <string>
#include <vector>

#include "commands/sections_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_sections(CLI::App& parent) {
  struct Options {
    std::string dir;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = parent.add_subcommand(
      "sections", "draw a wedge run's cross-sections: horizons, faults, displacement vectors as frames, "
                  "animations and PDF/SVG stills (python3 -m orogen.charts.sections RUN --help: the options; "
                  "docs/rendering.md)");
  cmd->add_option("dir", o->dir, "a wedge run folder")->required();
  cmd->allow_extras();
  cmd->prefix_command(false);
  return {cmd, [o, cmd] { return sections_command({o->dir, cmd->remaining()}); }};
}

}  // namespace orogen::cli
