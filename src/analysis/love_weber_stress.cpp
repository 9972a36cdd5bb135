#include "analysis/love_weber_stress.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace orogen {
namespace {

// f (x) l onto disc i's sums.
void add(DiscStress& s, std::size_t i, double fx, double fy, double lx, double ly) {
  s.xx[i] += fx * lx; s.xy[i] += fx * ly;
  s.yx[i] += fy * lx; s.yy[i] += fy * ly;
}

}  // namespace

DiscStress love_weber_stress(const Discs& d, const ContactList& c) {
  const std::size_t n = d.size();
  DiscStress s{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n), std::vector<double>(n),
               std::vector<double>(n)};
  for (std::size_t k = 0; k < c.size(); ++k) {
    const auto b = static_cast<std::size_t>(c.index_b[k]);
    add(s, b, c.fx[k], c.fy[k], c.x[k] - d.x[b], c.y[k] - d.y[b]);
    if (c.is_wall[k]) continue;
    const auto a = static_cast<std::size_t>(c.index_a[k]);
    add(s, a, -c.fx[k], -c.fy[k], c.x[k] - d.x[a], c.y[k] - d.y[a]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    s.area[i] = std::numbers::pi * d.radius[i] * d.radius[i];
    s.xx[i] /= s.area[i]; s.xy[i] /= s.area[i];
    s.yx[i] /= s.area[i]; s.yy[i] /= s.area[i];
  }
  return s;
}

StressGrid coarse_grain_stress(const Discs& d, const DiscStress& s, double cell) {
  StressGrid g;
  g.cell = cell;
  if (d.size() == 0) return g;
  const auto [xlo, xhi] = std::minmax_element(d.x.begin(), d.x.end());
  const auto [ylo, yhi] = std::minmax_element(d.y.begin(), d.y.end());
  g.x0 = std::floor(*xlo / cell) * cell;
  g.y0 = std::floor(*ylo / cell) * cell;
  g.nx = static_cast<std::size_t>(std::floor((*xhi - g.x0) / cell)) + 1;
  g.ny = static_cast<std::size_t>(std::floor((*yhi - g.y0) / cell)) + 1;
  const std::size_t cells = g.nx * g.ny;
  g.xx.assign(cells, 0.0); g.xy.assign(cells, 0.0); g.yx.assign(cells, 0.0); g.yy.assign(cells, 0.0);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto ix = std::min(g.nx - 1, static_cast<std::size_t>(std::max(0.0, std::floor((d.x[i] - g.x0) / cell))));
    const auto iy = std::min(g.ny - 1, static_cast<std::size_t>(std::max(0.0, std::floor((d.y[i] - g.y0) / cell))));
    const std::size_t k = iy * g.nx + ix;
    g.xx[k] += s.xx[i] * s.area[i]; g.xy[k] += s.xy[i] * s.area[i];
    g.yx[k] += s.yx[i] * s.area[i]; g.yy[k] += s.yy[i] * s.area[i];
  }
  const double a = cell * cell;
  for (std::size_t k = 0; k < cells; ++k) {
    g.xx[k] /= a; g.xy[k] /= a; g.yx[k] /= a; g.yy[k] /= a;
  }
  return g;
}

}  // namespace orogen
