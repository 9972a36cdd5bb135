#include "boundary/wall.hpp"

#include <algorithm>
#include <cmath>

namespace orogen {

double Wall::length() const { return std::hypot(bx - ax, by - ay); }

double closest_point_on_segment(const Wall& w, double px, double py, double& cx, double& cy) {
  const double ex = w.bx - w.ax, ey = w.by - w.ay;
  const double len2 = ex * ex + ey * ey;
  double s = len2 > 0 ? ((px - w.ax) * ex + (py - w.ay) * ey) / len2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  cx = w.ax + s * ex;
  cy = w.ay + s * ey;
  const double dx = px - cx, dy = py - cy;
  return dx * dx + dy * dy;
}

}  // namespace orogen
