// `orogen sections DIR [OPTIONS]`: a wedge run's cross-sections (src/commands/sections_command,
// orogen.charts.sections); the options are the module's, checked there.
#include "commands/sections_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_sections(CLI::App& parent) {
  return add_package_subcommand(
      parent, {"sections",
               "draw a wedge run's cross-sections: horizons, faults, displacement vectors as frames, animations and "
               "PDF/SVG stills (python3 -m orogen.charts.sections RUN --help: the options; docs/rendering.md)",
               "dir", "a wedge run folder",
               [](const std::string& dir, std::vector<std::string> rest) { return sections_command({dir, std::move(rest)}); }});
}

}  // namespace orogen::cli
