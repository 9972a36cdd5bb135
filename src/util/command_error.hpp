#pragma once
// How every command ends on an error, in one place: an exception becomes one line on stderr
// and the command's exit code. 2: input the message names as wrong (a key, a folder, a file
// that is not what the command takes): BadInput, or a CommandError thrown with that code.
// 1: anything else (a file that cannot be written or read, a full disk, out of memory).
#include <stdexcept>
#include <string>
#include <string_view>

namespace orogen {

inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

// An error whose exit code is chosen where it is thrown.
class CommandError : public std::runtime_error {
 public:
  CommandError(int exit_code, const std::string& message) : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }
  // The line the user reads: "error: " and the message (an error whose message is a whole
  // sentence of its own, as a configuration error's, says so by overriding this).
  virtual std::string line() const { return "error: " + std::string(what()); }

 private:
  int exit_code_;
};

class BadInput : public CommandError {
 public:
  explicit BadInput(const std::string& message) : CommandError(kExitBadInput, message) {}
};

// Writes the error's line to stderr and returns its exit code: a CommandError's own; for any
// other exception `otherwise`, with "CONTEXT: " before its message ("analyze runs/a: ...",
// none when empty), and out of memory said in those words.
int report_error(const std::exception& error, std::string_view context = "", int otherwise = kExitFailed);

// Runs a command's body; what it throws ends as report_error says.
template <class Body>
int run_reporting_errors(std::string_view context, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    return report_error(e, context);
  }
}

}  // namespace orogen
