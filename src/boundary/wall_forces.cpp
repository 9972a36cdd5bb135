#include "boundary/wall_forces.hpp"

#include <algorithm>
#include <cmath>

namespace orogen {

namespace {

// What every contact with a wall needs of it, computed once per step rather than per contact.
struct WallFrame {
  double ex = 0, ey = 0;        // unit vector from a to b
  double inv_len2 = 0;          // 1 / |b - a|^2 (0 for a point)
  double surface_vx = 0, surface_vy = 0;  // velocity of the wall's surface
};

WallFrame wall_frame(const Wall& w) {
  WallFrame f;
  const double dx = w.bx - w.ax, dy = w.by - w.ay, len2 = dx * dx + dy * dy;
  if (len2 > 0) {
    const double len = std::sqrt(len2);
    f.ex = dx / len;
    f.ey = dy / len;
    f.inv_len2 = 1.0 / len2;
  }
  f.surface_vx = w.vx + w.surface_speed * f.ex;
  f.surface_vy = w.vy + w.surface_speed * f.ey;
  return f;
}

}  // namespace

void add_wall_forces(NeighborList& L, const Discs& d, const std::vector<Wall>& walls, const ContactLaw& law,
                     double dt, std::vector<DiscForce>& forces) {
  auto& wc = L.walls;
  std::vector<WallFrame> frames;
  frames.reserve(walls.size());
  for (const auto& w : walls) frames.push_back(wall_frame(w));
  for (std::size_t k = 0; k < wc.size(); ++k) {
    const auto& w = walls[wc.wall[k]];
    const auto& frame = frames[wc.wall[k]];
    const auto i = wc.disc[k];
    wc.touching[k] = 0;
    wc.at_limit[k] = 0;
    // Closest point of the segment to the disc centre.
    const double s = std::clamp(((d.x[i] - w.ax) * (w.bx - w.ax) + (d.y[i] - w.ay) * (w.by - w.ay)) * frame.inv_len2,
                                0.0, 1.0);
    const double cx = w.ax + s * (w.bx - w.ax), cy = w.ay + s * (w.by - w.ay);
    const double dist2 = (d.x[i] - cx) * (d.x[i] - cx) + (d.y[i] - cy) * (d.y[i] - cy);
    const double r = d.radius[i];
    if (dist2 >= r * r || dist2 == 0.0) { wc.xi[k] = 0; continue; }
    const double dist = std::sqrt(dist2);
    const double nx = (d.x[i] - cx) / dist, ny = (d.y[i] - cy) / dist;  // wall -> disc
    const double tx = -ny, ty = nx;
    const double delta = r - dist;
    // Velocity of the disc's contact point (at -r n) relative to the wall's surface.
    const double rvx = d.vx[i] - d.omega[i] * r * tx - frame.surface_vx;
    const double rvy = d.vy[i] - d.omega[i] * r * ty - frame.surface_vy;
    const double vn = rvx * nx + rvy * ny;  // > 0 when separating
    const double vt = rvx * tx + rvy * ty;
    const double gn = wc.gamma_n[k];
    double fn = law.kn * delta - gn * vn;
    if (fn < 0) fn = 0;
    double ft = 0;
    const double limit = w.mu * fn;
    switch (w.friction) {
      case WallFriction::Smooth:
        wc.xi[k] = 0;
        break;
      case WallFriction::Rough:
        wc.xi[k] += vt * dt;
        ft = -law.ks * wc.xi[k] - law.tangential_damping_ratio * gn * vt;
        if (std::fabs(ft) > limit) {
          ft = std::copysign(limit, ft);
          wc.xi[k] = -ft / law.ks;
          wc.at_limit[k] = 1;
        }
        break;
      case WallFriction::Traction: {
        // Eq. 4.1 with the drag taken implicitly over the step, gamma / (1 + gamma dt / m):
        // stable for any gamma, and at most the force that brings a free disc to the
        // plate's speed in one step.
        const double gamma = w.traction_gamma / (1.0 + w.traction_gamma * dt / wc.mass[k]);
        ft = -gamma * vt;
        if (std::fabs(ft) > limit) {
          ft = std::copysign(limit, ft);
          wc.at_limit[k] = 1;
        }
        break;
      }
    }
    wc.touching[k] = 1;
    forces[i].fx += fn * nx + ft * tx;
    forces[i].fy += fn * ny + ft * ty;
    forces[i].torque += -r * ft;
  }
}

}  // namespace orogen
