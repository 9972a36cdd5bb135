#include <charconv>
#include <string>

#include "subcommand.hpp"

namespace orogen::cli {

CLI::Validator not_empty() {
  return CLI::Validator(
      [](std::string& value) { return value.empty() ? std::string("an empty value (a number is needed)") : ""; }, "",
      "not empty");
}

CLI::Validator count_in(long long lo, long long hi) {
  return CLI::Validator(
      [lo, hi](std::string& value) {
        long long v = 0;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
        const bool ok = !value.empty() && ec == std::errc() && end == value.data() + value.size() &&
                        value.front() != '-' && v >= lo && v <= hi;
        return ok ? std::string()
                  : "'" + value + "' must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
      },
      "", "count");
}

}  // namespace orogen::cli
