// `orogen calibrate CONFIG --out DIR [OPTIONS]`: a material's Mohr-Coulomb envelopes from biaxial
// tests (src/commands/calibrate_command, orogen.calibrate); the options are the module's,
// checked there.
#include <memory>
#include <string>
#include <vector>

#include "commands/calibrate_command.hpp"
#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_calibrate(CLI::App& parent) {
  struct Options {
    std::string config;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = parent.add_subcommand(
      "calibrate", "measure a material: biaxial tests at several confining stresses, its peak and residual "
                   "friction angle, cohesion and UCS with the stress-strain curves (python3 -m orogen.calibrate "
                   "--help: the options; docs/materials.md)");
  cmd->add_option("config", o->config, "a configuration holding the material")->required();
  cmd->allow_extras();
  cmd->prefix_command(false);
  return {cmd, [o, cmd] { return calibrate_command({o->config, cmd->remaining()}); }};
}

}  // namespace orogen::cli
