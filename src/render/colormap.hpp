#pragma once
// Colours for the renderer: perceptual colormaps for scalar fields, banded horizon colours
// for initial depth (the thesis's horizon plots) and hashed colours for clusters.
#include <cstdint>
#include <span>

namespace orogen {

// RGB components in [0, 1] (sRGB, as written to the PNG).
struct Rgb {
  double r = 0, g = 0, b = 0;
};

// Force: pale orange -> red -> near black, for force lines over pale discs (strong = dark).
enum class Colormap { Viridis, Hot, Force };

// Colour at t in [0, 1] (clamped; NaN gives mid grey) by linear interpolation in a small table.
Rgb colormap_sample(Colormap map, double t);

struct ValueRange {
  double lo = 0, hi = 1;
};

// Percentile range of the finite values (default 1st to 99th) so that a few outliers do not
// wash out the colour scale. Returns {0, 1} for no finite values and widens a zero-width range.
ValueRange robust_range(std::span<const double> values, double lo_pct = 1.0, double hi_pct = 99.0);

// Number of colours horizon_color cycles through.
constexpr int kMaxHorizonColors = 4;

// Colour of the horizon band holding depth0: bands of thickness `band` alternate through
// `n_colors` (2 or 4) earthy colours; pro-side material is drawn in a lighter shade.
Rgb horizon_color(double depth0, double band, int n_colors, bool pro_side);

// A stable, well-spread colour per cluster id; free discs (id < 0) are light grey.
Rgb cluster_color(std::int64_t cluster_id);

// Mixes c with white by `amount` in [0, 1].
Rgb lighten(Rgb c, double amount);

// Darker version of c (for outlines), scaled by `factor` in [0, 1].
Rgb darken(Rgb c, double factor);

}  // namespace orogen
