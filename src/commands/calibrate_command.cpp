#include "commands/calibrate_command.hpp"

#include "util/python_module.hpp"

namespace orogen {

int calibrate_command(const CalibrateOptions& options) {
  std::vector<std::string> args = {options.config};
  args.insert(args.end(), options.module_options.begin(), options.module_options.end());
  return run_package_command("orogen.calibrate", "orogen calibrate", args);
}

}  // namespace orogen
