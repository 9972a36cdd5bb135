#pragma once
// The upper surface of the material (MODEL §8): columns of fixed width along x; the top of the
// highest disc in a column defines the surface there.
#include <cstddef>
#include <vector>

#include "particles/discs.hpp"

namespace orogen {

struct Surface {
  double x_lo = 0, width = 1;      // left edge of column 0 and column width
  std::vector<double> height;      // top of the highest disc (y + r); NaN for an empty column
  std::vector<std::int64_t> top;   // disc id of the highest disc, -1 if empty
  std::vector<std::size_t> top_index;  // its index in the discs measured (valid until they change)

  std::size_t column_of(double x) const;
  double column_centre(std::size_t k) const { return x_lo + (static_cast<double>(k) + 0.5) * width; }
  // Surface height at x, taken from the column holding x (NaN if empty).
  double at(double x) const;
};

// More columns than this is an input error (a column width near zero, a layer of 1e300 d).
constexpr double kMaxSurfaceColumns = 1e9;

// Builds the surface from all discs, columns of the given width starting at x_lo.
Surface measure_surface(const Discs& discs, double x_lo, double x_hi, double column_width);

// Mean disc radius (used for the column width 2.3 R_mean).
double mean_radius(const Discs& discs);

}  // namespace orogen
