#pragma once
// removals.csv: every particle removed from the model (left the domain, eroded, trimmed).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "world/world.hpp"

namespace orogen {

// `through_step`: every removal up to this time step is listed (the file says so in a `#`
// line, so that a reader of a running run knows which outputs it covers).
void write_removal_log(const std::filesystem::path& path, const std::vector<RemovalRecord>& removals,
                       std::uint64_t through_step);

// The first row of the removals file at `path` that disagrees with `removals` (a checkpoint's
// list), described for a message; "" when they agree or there is no file. The checkpoint's
// removals must be the file's first rows; rows after them with steps after `through_step` were
// written after that checkpoint and are not compared. A resume refuses a folder whose file is
// of another run.
std::string removal_log_difference(const std::filesystem::path& path, const std::vector<RemovalRecord>& removals,
                                   std::uint64_t through_step);

}  // namespace orogen
