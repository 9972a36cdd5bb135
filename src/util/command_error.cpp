#include "util/command_error.hpp"

#include <iostream>
#include <new>

namespace orogen {

int report_error(const std::exception& error, std::string_view context, int otherwise) {
  if (const auto* e = dynamic_cast<const CommandError*>(&error)) {
    std::cerr << e->line() << "\n";
    return e->exit_code();
  }
  const std::string prefix = context.empty() ? "error: " : "error: " + std::string(context) + ": ";
  if (dynamic_cast<const std::bad_alloc*>(&error)) std::cerr << prefix << "out of memory\n";
  else std::cerr << prefix << error.what() << "\n";
  return otherwise;
}

}  // namespace orogen
