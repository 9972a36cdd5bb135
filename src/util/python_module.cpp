#include "util/python_module.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <iostream>

namespace orogen {

namespace {

int wait_for(pid_t pid) {
  int raw = 0;
  while (::waitpid(pid, &raw, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFEXITED(raw)) return WEXITSTATUS(raw);
  return WIFSIGNALED(raw) ? 128 + WTERMSIG(raw) : 127;
}

// fork + execv of kPython with ARGV (argv[0] included); stdout to stderr on request.
int run_python(const std::vector<std::string>& argv, bool stdout_to_stderr, bool quiet) {
  std::vector<char*> raw;
  for (const std::string& a : argv) raw.push_back(const_cast<char*>(a.c_str()));
  raw.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (quiet) {
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    } else if (stdout_to_stderr) {
      ::dup2(STDERR_FILENO, STDOUT_FILENO);
    }
    ::execv(kPython, raw.data());
    ::_exit(127);
  }
  return pid < 0 ? 127 : wait_for(pid);
}

}  // namespace

std::string python_module_unavailable(const std::string& module) {
  std::error_code ec;
  if (!std::filesystem::exists(kPython, ec))
    return std::string(kPython) + " is missing (install Debian's python3: scripts/install-deps.sh)";
  // find_spec imports the parent packages only: quick, and it needs nothing the module needs.
  const std::string probe = "import importlib.util, sys; sys.exit(0 if importlib.util.find_spec('" + module +
                            "') else 3)";
  if (run_python({kPython, "-c", probe}, false, true) != 0)
    return "the Python package orogen (module " + module + ") is not installed for " + kPython +
           " (scripts/install-python.sh installs it; or set PYTHONPATH to the source tree's python/ folder)";
  return "";
}

int run_python_module(const std::string& module, const std::vector<std::string>& args, bool stdout_to_stderr) {
  std::vector<std::string> argv = {kPython, "-m", module};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_python(argv, stdout_to_stderr, false);
}

int run_package_command(const std::string& module, const std::string& what, const std::vector<std::string>& args) {
  if (const std::string why = python_module_unavailable(module); !why.empty()) {
    std::cerr << "error: " << what << " needs " << why << "\n";
    return 1;
  }
  return run_python_module(module, args);
}

}  // namespace orogen
