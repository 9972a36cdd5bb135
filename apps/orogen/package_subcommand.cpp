// The subcommands whose options a module of the Python package reads (`orogen sections`,
// `orogen calibrate`): one required positional argument, every other word passed on as given.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "subcommand.hpp"

namespace orogen::cli {

Subcommand add_package_subcommand(CLI::App& parent, const PackageSubcommand& spec) {
  auto first = std::make_shared<std::string>();
  auto* cmd = parent.add_subcommand(spec.name, spec.description);
  cmd->add_option(spec.positional, *first, spec.positional_help)->required();
  cmd->allow_extras();
  cmd->prefix_command(false);
  const auto run = spec.run;
  return {cmd, [first, cmd, run] { return run(*first, cmd->remaining()); }};
}

}  // namespace orogen::cli
