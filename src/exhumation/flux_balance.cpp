#include "exhumation/flux_balance.hpp"

#include <limits>

namespace orogen {

FluxBalance flux_balance(std::span<const double> time, std::span<const double> eroded_area, double flux_in,
                         int window, double fraction) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = time.size();
  const auto w = static_cast<std::size_t>(window);
  FluxBalance f;
  f.flux_out.assign(n, nan);
  f.mean_out.assign(n, nan);
  f.ratio.assign(n, nan);
  double sum = 0;  // eroded area of the last w intervals
  for (std::size_t k = 1; k < n; ++k) {
    const double dt = time[k] - time[k - 1];
    if (dt > 0) f.flux_out[k] = eroded_area[k] / dt;
    sum += eroded_area[k];
    if (k > w) sum -= eroded_area[k - w];
    if (k < w) continue;
    const double span = time[k] - time[k - w];
    if (!(span > 0)) continue;
    f.mean_out[k] = sum / span;
    f.ratio[k] = f.mean_out[k] / flux_in;
    if (f.steady_output < 0 && f.ratio[k] >= fraction) f.steady_output = static_cast<std::int64_t>(k);
  }
  return f;
}

}  // namespace orogen
