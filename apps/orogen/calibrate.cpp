// `orogen calibrate CONFIG --out DIR [OPTIONS]`: a material's Mohr-Coulomb envelopes from biaxial
// tests (src/commands/calibrate_command, orogen.calibrate); the options are the module's,
// checked there.
#include "commands/calibrate_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_calibrate(CLI::App& parent) {
  return add_package_subcommand(
      parent, {"calibrate",
               "measure a material: biaxial tests at several confining stresses, its peak and residual friction "
               "angle, cohesion and UCS with the stress-strain curves (python3 -m orogen.calibrate --help: the "
               "options; docs/materials.md)",
               "config", "a configuration holding the material",
               [](const std::string& config, std::vector<std::string> rest) {
                 return calibrate_command({config, std::move(rest)});
               }});
}

}  // namespace orogen::cli
