#include "commands/report_command.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <iostream>
#include <string>
#include <system_error>

#include "run/run_folder.hpp"

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
  const fs::path package = fs::path(OROGEN_SOURCE_DIR) / "python" / "atlas";
  const char* python = "/usr/bin/python3";
  if (!fs::exists(python) || !fs::exists(package / "__main__.py")) {
    std::cerr << "error: the atlas needs " << python << " and " << package.string() << " (the source tree this "
              << "orogen was built from)\n";
    return 1;
  }
  const std::string p = package.string(), d = options.dir.string(), o = options.out.string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (o.empty()) ::execl(python, python, p.c_str(), d.c_str(), static_cast<char*>(nullptr));
    else ::execl(python, python, p.c_str(), d.c_str(), "--out", o.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  if (pid < 0) {
    std::cerr << "error: cannot start " << python << "\n";
    return 1;
  }
  int raw = 0;
  while (::waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 1;
}

}  // namespace orogen
