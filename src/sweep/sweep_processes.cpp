#include "sweep/sweep_processes.hpp"

#include "parallel/mpi_session.hpp"
#include "util/timestamp.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <stdexcept>

namespace orogen {
pid_t spawn_self(const std::vector<std::string>& args, const std::filesystem::path& log) {
  // Everything the child needs is prepared before fork: between fork and exec only
  // async-signal-safe calls are allowed.
  std::vector<std::string> argv_text = {"orogen"};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : argv_text) argv.push_back(s.data());
  argv.push_back(nullptr);
  // The child is one process of its own even where this one is an MPI rank (an ensemble under
  // mpirun): without the launcher's variables, its `orogen run` does not take itself for a rank.
  std::vector<char*> envp;
  for (char** e = environ; *e; ++e)
    if (!MpiSession::launcher_variable(*e)) envp.push_back(*e);
  envp.push_back(nullptr);

  const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (out < 0) throw std::runtime_error(fmt::format("cannot open {}: {}", log.string(), std::strerror(errno)));
  {
    // A header per attempt, so that the log of a resumed or retried run reads in order.
    std::string header = "=== " + local_timestamp() + " orogen";
    for (const auto& a : args) header += " " + a;
    header += "\n";
    [[maybe_unused]] const auto n = ::write(out, header.data(), header.size());
  }
  const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (in < 0) {
    ::close(out);
    throw std::runtime_error(fmt::format("cannot open /dev/null: {}", std::strerror(errno)));
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {
    // Die with the sweep; if it already died before prctl took effect, stop now.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(128 + SIGTERM);
    ::dup2(in, STDIN_FILENO);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    ::close_range(3, ~0U, 0);  // no sweep file descriptors (the lock, other logs) in the child
    // /proc/self/exe is this executable even if the file was rebuilt since the sweep started.
    ::execve("/proc/self/exe", argv.data(), envp.data());
    static const char msg[] = "orogen sweep: cannot execute /proc/self/exe\n";
    [[maybe_unused]] const auto n = ::write(STDERR_FILENO, msg, sizeof msg - 1);
    ::_exit(127);
  }
  const int fork_errno = errno;
  ::close(out);
  ::close(in);
  if (pid < 0) throw std::runtime_error(fmt::format("cannot start a child process: {}", std::strerror(fork_errno)));
  return pid;
}

std::optional<ChildExit> reap_child() {
  int raw = 0;
  pid_t pid;
  do {
    pid = ::waitpid(-1, &raw, WNOHANG);
  } while (pid < 0 && errno == EINTR);
  if (pid <= 0) return std::nullopt;
  const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : WIFSIGNALED(raw) ? 128 + WTERMSIG(raw) : -1;
  return ChildExit{pid, status};
}

}  // namespace orogen
