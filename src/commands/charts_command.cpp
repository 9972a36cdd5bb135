#include "commands/charts_command.hpp"

#include <string>
#include <vector>

#include "util/python_module.hpp"

namespace orogen {

int charts_command(const ChartsOptions& options) {
  std::vector<std::string> args = {options.dir.string()};
  if (!options.out.empty()) args.insert(args.end(), {"--out", options.out.string()});
  return run_package_command("orogen.charts", "orogen charts", args);
}

}  // namespace orogen
