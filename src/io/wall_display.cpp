#include "io/wall_display.hpp"

#include <algorithm>

namespace orogen {

std::vector<std::array<double, 4>> walls_for_display(const std::vector<std::array<double, 4>>& walls,
                                                     const std::vector<double>& x, const std::vector<double>& y) {
  if (x.empty()) return walls;
  const auto [x_lo, x_hi] = std::minmax_element(x.begin(), x.end());
  const auto [y_lo, y_hi] = std::minmax_element(y.begin(), y.end());
  const double margin = std::max({*x_hi - *x_lo, *y_hi - *y_lo, 1.0});
  const double lo[2] = {*x_lo - margin, *y_lo - margin}, hi[2] = {*x_hi + margin, *y_hi + margin};
  std::vector<std::array<double, 4>> out;
  for (const auto& w : walls) {
    // Liang-Barsky: the part t in [t0, t1] of a + t (b - a) inside the box.
    const double a[2] = {w[0], w[1]}, d[2] = {w[2] - w[0], w[3] - w[1]};
    double t0 = 0, t1 = 1;
    bool inside = true;
    for (int k = 0; k < 2 && inside; ++k) {
      if (d[k] == 0) {
        inside = a[k] >= lo[k] && a[k] <= hi[k];
        continue;
      }
      double ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      inside = t0 <= t1;
    }
    if (!inside) continue;
    // Ends inside the box are kept bit for bit.
    const bool keep_a = t0 == 0, keep_b = t1 == 1;
    out.push_back({keep_a ? w[0] : a[0] + t0 * d[0], keep_a ? w[1] : a[1] + t0 * d[1],
                   keep_b ? w[2] : a[0] + t1 * d[0], keep_b ? w[3] : a[1] + t1 * d[1]});
  }
  return out;
}

}  // namespace orogen
