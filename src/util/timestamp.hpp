#pragma once
#include <string>

namespace orogen {
// Local wall-clock time as "YYYY-MM-DD HH:MM:SS" (the run log's format), for the sweep's logs.
std::string local_timestamp();
}  // namespace orogen
