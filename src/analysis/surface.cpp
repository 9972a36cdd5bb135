#include "analysis/surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace orogen {

std::size_t Surface::column_of(double x) const {
  const double k = std::floor((x - x_lo) / width);
  if (k < 0) return 0;
  // Compared as doubles first: casting a k beyond size_t (or NaN) would be undefined.
  if (!(k < static_cast<double>(height.size()))) return height.size() - 1;
  return static_cast<std::size_t>(k);
}

double Surface::at(double x) const {
  if (height.empty()) return std::numeric_limits<double>::quiet_NaN();
  return height[column_of(x)];
}

Surface measure_surface(const Discs& d, double x_lo, double x_hi, double column_width) {
  Surface s;
  s.x_lo = x_lo;
  s.width = column_width;
  const double columns = std::max(1.0, std::ceil((x_hi - x_lo) / column_width));
  // Configurations are checked for this with key names (check_material_size); a library caller
  // gets an exception rather than a cast of inf or a vector of 1e20 columns.
  if (!(columns <= kMaxSurfaceColumns))
    throw std::length_error("measure_surface: " + std::to_string(columns) + " columns of width " +
                            std::to_string(column_width) + " over [" + std::to_string(x_lo) + ", " +
                            std::to_string(x_hi) + "]");
  const auto n = static_cast<std::size_t>(columns);
  s.height.assign(n, std::numeric_limits<double>::quiet_NaN());
  s.top.assign(n, -1);
  s.top_index.assign(n, 0);
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (d.x[i] < x_lo || d.x[i] >= x_lo + static_cast<double>(n) * column_width) continue;
    const auto k = s.column_of(d.x[i]);
    const double top = d.y[i] + d.radius[i];
    // Ties go to the smaller id so that the result does not depend on array order.
    if (!(top <= s.height[k]) || (top == s.height[k] && d.id[i] < s.top[k])) {
      s.height[k] = top;
      s.top[k] = d.id[i];
      s.top_index[k] = i;
    }
  }
  return s;
}

double mean_radius(const Discs& d) {
  if (d.size() == 0) return 0.5;
  double sum = 0;
  for (double r : d.radius) sum += r;
  return sum / static_cast<double>(d.size());
}

}  // namespace orogen
