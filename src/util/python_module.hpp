#pragma once
// Runs a module of the Python package `orogen` (python/orogen, docs/python.md) as a child
// process: `/usr/bin/python3 -m MODULE ARGS...`, the way a user would. The package is found
// by Python itself (installed by scripts/install-python.sh, or on PYTHONPATH), never by a
// path of the source tree, so an installed orogen keeps working when the source moves.
#include <string>
#include <vector>

namespace orogen {

// The interpreter the package is installed into (Debian's python3).
inline constexpr const char* kPython = "/usr/bin/python3";

// Why MODULE cannot be run here (no interpreter, or the package is not importable), as one
// sentence that says how to fix it; "" when it can.
std::string python_module_unavailable(const std::string& module);

// Runs MODULE with ARGS and waits; its stdout goes to our stderr when stdout_to_stderr
// (a command whose own stdout is for data). Returns the module's exit status, 128+N when it
// died by signal N, 127 when it could not be started.
int run_python_module(const std::string& module, const std::vector<std::string>& args, bool stdout_to_stderr = false);

// A command that is a module of the package (`orogen charts`, `orogen report`): runs it with
// ARGS, its exit status ours; where it cannot run, "error: WHAT needs ..." and exit 1.
int run_package_command(const std::string& module, const std::string& what, const std::vector<std::string>& args);

}  // namespace orogen
