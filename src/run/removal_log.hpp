#pragma once
// removals.csv: every particle removed from the model (left the domain, eroded, trimmed).
#include <filesystem>
#include <vector>

#include "world/world.hpp"

namespace orogen {

void write_removal_log(const std::filesystem::path& path, const std::vector<RemovalRecord>& removals);

}  // namespace orogen
