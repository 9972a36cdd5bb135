#include "boundary/traction_mass.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace orogen {
namespace {

// 1 / (effective tangential mass) of disc i's body at its closest point to the wall.
double inverse_tangential_mass(const Discs& d, const Clusters& c, const Wall& wall, std::size_t i) {
  double cx, cy;
  const double dist = std::sqrt(closest_point_on_segment(wall, d.x[i], d.y[i], cx, cy));
  const double nx = dist > 0 ? (d.x[i] - cx) / dist : 0.0, ny = dist > 0 ? (d.y[i] - cy) / dist : 0.0;
  const double r = d.radius[i];
  if (d.cluster[i] < 0) return d.inv_mass[i] + r * r * d.inv_inertia[i];
  const auto k = static_cast<std::size_t>(d.cluster[i]);
  // Lever of the contact point p = x_i - r n about the body's centre, along n; with no normal
  // (a disc centred on the wall) its whole length, the largest it can be.
  const double px = d.x[i] - r * nx - c.x[k], py = d.y[i] - r * ny - c.y[k];
  const double lever2 = dist > 0 ? (px * nx + py * ny) * (px * nx + py * ny) : px * px + py * py;
  return c.inv_mass[k] + lever2 * c.inv_inertia[k];
}

}  // namespace

void set_traction_mass(WallContacts& wc, const Discs& d, const Clusters& c, const std::vector<Wall>& walls) {
  wc.traction_mass.resize(wc.size());
  std::vector<std::uint32_t> on_wall(c.size(), 0);  // a body's contacts with the current wall
  for (std::size_t begin = 0; begin < wc.size();) {
    std::size_t end = begin;
    while (end < wc.size() && wc.wall[end] == wc.wall[begin]) ++end;
    for (std::size_t k = begin; k < end; ++k)
      if (d.cluster[wc.disc[k]] >= 0) ++on_wall[static_cast<std::size_t>(d.cluster[wc.disc[k]])];
    const Wall& wall = walls[wc.wall[begin]];
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = wc.disc[k];
      const auto body = d.cluster[i];
      const double shared_by = body >= 0 ? on_wall[static_cast<std::size_t>(body)] : 1.0;
      wc.traction_mass[k] = d.is_dynamic(i) ? 1.0 / (inverse_tangential_mass(d, c, wall, i) * shared_by)
                                            : std::numeric_limits<double>::infinity();
    }
    for (std::size_t k = begin; k < end; ++k)
      if (d.cluster[wc.disc[k]] >= 0) on_wall[static_cast<std::size_t>(d.cluster[wc.disc[k]])] = 0;
    begin = end;
  }
}

}  // namespace orogen
