#pragma once
// The first job of a list build: are all positions finite (a blown-up run must stop before
// binning), and the largest stable id and radius (the sizes of the history index and cells).
#include <cstdint>

#include "particles/discs.hpp"

namespace orogen {

struct DiscScan {
  bool finite = true;
  std::int64_t max_id = 0;
  double r_max = 0;
};

DiscScan scan_discs(const Discs& discs);

}  // namespace orogen
