#pragma once
// The line that says why a sweep's run failed: the last line its latest attempt wrote to the
// run's log, for the results table and the failed-run marker.
#include <filesystem>
#include <string>

namespace orogen {

// The last non-empty line after the log's last "=== " attempt header, its "[time] " prefix
// removed, cut to 300 characters; empty if the log is missing or holds nothing of the attempt.
std::string last_log_line(const std::filesystem::path& log);

}  // namespace orogen
