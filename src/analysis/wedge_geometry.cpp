#include "analysis/wedge_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace orogen {

double fitted_slope(const Surface& s, double x_lo, double x_hi) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < s.height.size(); ++k) {
    const double x = s.column_centre(k);
    if (x < x_lo || x > x_hi || !std::isfinite(s.height[k])) continue;
    n += 1; sx += x; sy += s.height[k]; sxx += x * x; sxy += x * s.height[k];
  }
  const double den = n * sxx - sx * sx;
  if (n < 2 || den <= 0) return 0.0;
  return std::atan((n * sxy - sx * sy) / den);
}

namespace {

// FrontRule::Surface: the extreme x of the discs above `height` that lie in stretches of
// surface columns holding such discs (gaps up to max_bridged_gap bridged) at least
// min_raised_width wide; false if none.
bool stretch_fronts(const WedgeGeometryInput& in, const Surface& s, double height, double& pro, double& retro) {
  const std::size_t n = s.height.size();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> lo(n, inf), hi(n, -inf);  // extreme x of the raised discs per column
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    if (!(in.y[i] > height) || n == 0) continue;
    const std::size_t k = s.column_of(in.x[i]);
    lo[k] = std::min(lo[k], in.x[i]);
    hi[k] = std::max(hi[k], in.x[i]);
  }
  // A stretch runs from a raised column over gaps of at most max_gap columns to the last
  // raised column before a wider gap.
  const auto max_gap = static_cast<std::size_t>(std::floor(in.max_bridged_gap / s.width));
  bool found = false;
  for (std::size_t k = 0; k < n;) {
    if (!std::isfinite(lo[k])) { ++k; continue; }
    std::size_t last = k, next = k + 1;
    while (next < n && next - last <= max_gap + 1) {
      if (std::isfinite(lo[next])) last = next;
      ++next;
    }
    if (static_cast<double>(last + 1 - k) * s.width >= in.min_raised_width) {
      if (!found) pro = lo[k];
      retro = hi[last];
      found = true;
    }
    k = last + 1;
  }
  return found;
}

}  // namespace

WedgeGeometry measure_wedge(const WedgeGeometryInput& in, const Surface& surface) {
  WedgeGeometry g;
  const double inf = std::numeric_limits<double>::infinity();
  double top = -inf;
  double dp = inf, dr = -inf, mp = inf, mr = -inf;
  const double front_y = in.h0 + in.d_max, marker_y = in.marker_height * in.h0;
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    const double t = in.y[i] + in.radius[i];
    if (t > top || (t == top && in.x[i] < g.x_peak)) { top = t; g.x_peak = in.x[i]; }
    if (in.y[i] > front_y) { dp = std::min(dp, in.x[i]); dr = std::max(dr, in.x[i]); }
    if (in.y[i] > marker_y) { mp = std::min(mp, in.x[i]); mr = std::max(mr, in.x[i]); }
  }
  if (in.front_rule == FrontRule::Surface) {
    dp = inf;  // the discs' extremes give way to the surface's raised stretches
    dr = -inf;
    stretch_fronts(in, surface, front_y, dp, dr);
  }
  g.has_front = std::isfinite(dp);
  g.h = std::isfinite(top) ? top - in.h0 : 0.0;
  g.dp = g.has_front ? dp : in.x_s;
  g.dr = g.has_front ? dr : in.x_s;
  g.mp = std::isfinite(mp) ? mp : in.x_s;
  g.mr = std::isfinite(mr) ? mr : in.x_s;
  if (!g.has_front) { g.x_peak = in.x_s; return g; }
  // Mean tapers: from the front (at the layer's top, h0) up to the peak.
  if (g.x_peak - g.dp > 0) g.alpha = std::atan(g.h / (g.x_peak - g.dp));
  if (g.dr - g.x_peak > 0) g.beta = std::atan(g.h / (g.dr - g.x_peak));
  g.alpha_fit = fitted_slope(surface, g.dp, g.x_peak);
  g.beta_fit = -fitted_slope(surface, g.x_peak, g.dr);
  return g;
}

}  // namespace orogen
