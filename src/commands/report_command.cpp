#include "commands/report_command.hpp"

#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "run/run_folder.hpp"
#include "util/python_module.hpp"

namespace orogen {

namespace fs = std::filesystem;

namespace {

// The argument checks the Python side repeats: here so that bad input is refused with no
// Python at all.
std::string input_error(const ReportOptions& o) {
  std::error_code ec;
  if (!fs::exists(o.dir, ec))
    return o.dir.string() + ": no such folder (give the folder that holds the runs, sweeps and ensembles)";
  if (!fs::is_directory(o.dir, ec))
    return o.dir.string() + ": not a folder (give the folder that holds the runs, sweeps and ensembles)";
  if (!o.out.empty() && fs::exists(o.out, ec) && !fs::is_directory(o.out, ec))
    return "--out " + o.out.string() + ": a file is there, not a folder";
  if (!o.out.empty()) return run_file_refusal("--out " + o.out.string(), o.out);
  return "";
}

}  // namespace

int report_command(const ReportOptions& options) {
  if (const std::string error = input_error(options); !error.empty()) {
    std::cerr << "error: " << error << "\n";
    return 2;
  }
  std::vector<std::string> args = {options.dir.string()};
  if (!options.out.empty()) args.insert(args.end(), {"--out", options.out.string()});
  return run_package_command("orogen.atlas", "the atlas", args);
}

}  // namespace orogen
