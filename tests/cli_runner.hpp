#pragma once
// Runs the `orogen` binary from a test: its exit status (128 + signal when it crashed) and
// what it printed.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "temp_dir_fixture.hpp"

namespace orogen::testing {

struct CliResult {
  int status = -1;  // exit status, or 128 + signal
  std::string out, err;
};

inline int decode_exit_status(int raw) {
  if (WIFEXITED(raw)) return WEXITSTATUS(raw);
  if (WIFSIGNALED(raw)) return 128 + WTERMSIG(raw);
  return -1;
}

// Runs `ENV orogen ARGS` through the shell (ARGS is shell syntax), capturing stdout and stderr
// in files under `scratch`; `env` is prefixed to the command line ("NAME=value ").
inline CliResult run_orogen(const std::string& args, const std::filesystem::path& scratch,
                            const std::string& env = "") {
  static int serial = 0;
  const auto out = scratch / ("cli_stdout_" + std::to_string(serial));
  const auto err = scratch / ("cli_stderr_" + std::to_string(serial++));
  const std::string cmd =
      env + "'" + std::string(OROGEN_BINARY) + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  CliResult r;
  r.status = decode_exit_status(std::system(cmd.c_str()));
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace orogen::testing
