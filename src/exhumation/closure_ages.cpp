#include "exhumation/closure_ages.hpp"

#include <cmath>
#include <limits>

namespace orogen {

void ClosureAges::observe(double time, double depth, std::span<const double> closure) {
  if (!seen_) {
    seen_ = true;
    first_time_ = time;
    max_depth_ = std::numeric_limits<double>::quiet_NaN();  // until a depth is measured
    for (auto& t : last_deep_) t = time;  // un-reset particles age from their first output
  }
  time_ = time;
  depth_ = depth;
  if (std::isnan(depth)) return;
  if (!(depth <= max_depth_)) max_depth_ = depth;  // NaN max: the first depth measured
  for (std::size_t i = 0; i < closure.size(); ++i) {
    const bool deep = depth > closure[i];
    if (deep) {
      last_deep_[i] = time;
      if (!deep_now_[i]) ++dips_[i];  // a new dip, not one that goes on
    }
    deep_now_[i] = deep;
  }
}

}  // namespace orogen
