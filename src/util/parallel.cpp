#include "util/parallel.hpp"

#include <omp.h>

#include <cerrno>
#include <cstdlib>
#include <optional>

namespace orogen {
namespace {
const char* kVariable = "OROGEN_MIN_PARALLEL_ITEMS";

// The variable's value; nullopt when it is set but not a whole number in [1, kMaxParallelItems]
// (strtoll clamps an overflowing value and sets errno, which must not pass as valid).
std::optional<std::ptrdiff_t> read_min_parallel_items() {
  const char* text = std::getenv(kVariable);
  if (text == nullptr || *text == '\0') return kMinParallelItems;
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text, &end, 10);
  if (*end != '\0' || errno == ERANGE || v < 1 || v > kMaxParallelItems) return std::nullopt;
  return static_cast<std::ptrdiff_t>(v);
}
}  // namespace

std::ptrdiff_t min_parallel_items() {
  static const std::ptrdiff_t value = read_min_parallel_items().value_or(kMinParallelItems);
  return value;
}

std::string parallel_environment_error() {
  if (read_min_parallel_items()) return "";
  return std::string("environment variable ") + kVariable + " = '" + std::getenv(kVariable) +
         "': must be a whole number from 1 to " + std::to_string(kMaxParallelItems) + " (unset: " + std::to_string(kMinParallelItems) + ")";
}
ItemRange thread_share(std::ptrdiff_t n) {
  const std::ptrdiff_t threads = omp_get_num_threads(), t = omp_get_thread_num();
  return {n * t / threads, n * (t + 1) / threads};
}

}  // namespace orogen
