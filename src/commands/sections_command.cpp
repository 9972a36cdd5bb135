#include "commands/sections_command.hpp"

#include "util/python_module.hpp"

namespace orogen {

int sections_command(const SectionsOptions& options) {
  std::vector<std::string> args = {options.dir.string()};
  args.insert(args.end(), options.module_options.begin(), options.module_options.end());
  return run_package_command("orogen.charts.sections", "orogen sections", args);
}

}  // namespace orogen
