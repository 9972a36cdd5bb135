#pragma once
// removals.csv: every particle removed from the model (left the domain, eroded, trimmed).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "world/world.hpp"

namespace orogen {

// `through_step`: every removal up to this time step is listed (the file says so in a `#`
// line, so that a reader of a running run knows which outputs it covers).
void write_removal_log(const std::filesystem::path& path, const std::vector<RemovalRecord>& removals,
                       std::uint64_t through_step);

}  // namespace orogen
