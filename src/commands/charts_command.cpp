#include "commands/charts_command.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "util/python_module.hpp"

namespace orogen {

int charts_command(const ChartsOptions& options) {
  if (const std::string why = python_module_unavailable("orogen.charts"); !why.empty()) {
    std::cerr << "error: the charts need " << why << "\n";
    return 1;
  }
  std::vector<std::string> args = {options.dir.string()};
  if (!options.out.empty()) args.insert(args.end(), {"--out", options.out.string()});
  return run_python_module("orogen.charts", args);
}

}  // namespace orogen
