#include "contact/disc_scan.hpp"

#include <algorithm>
#include <cmath>

namespace orogen {

DiscScan scan_discs(const Discs& d) {
  DiscScan s;
  for (std::size_t i = 0; i < d.size(); ++i) {
    s.max_id = std::max(s.max_id, d.id[i]);
    s.r_max = std::max(s.r_max, d.radius[i]);
    if (!std::isfinite(d.x[i]) || !std::isfinite(d.y[i])) s.finite = false;
  }
  return s;
}

}  // namespace orogen
