#include "boundary/wall_forces.hpp"

#include <cmath>
#include <utility>

namespace orogen {
namespace {

// Wall contacts [begin, end): force, history and flags of each, added onto its disc.
void contact_range(WallContacts& wc, const Discs& d, const std::vector<Wall>& walls, const ContactLaw& law,
                   double dt, DiscForce* forces, std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) {
    const auto& w = walls[wc.wall[k]];
    const auto i = wc.disc[k];
    wc.touching[k] = 0;
    wc.at_limit[k] = 0;
    double cx, cy;
    const double dist2 = closest_point_on_segment(w, d.x[i], d.y[i], cx, cy);
    const double r = d.radius[i];
    if (dist2 >= r * r || dist2 == 0.0) { wc.xi[k] = 0; continue; }
    const double dist = std::sqrt(dist2);
    const double nx = (d.x[i] - cx) / dist, ny = (d.y[i] - cy) / dist;  // wall -> disc
    const double tx = -ny, ty = nx;
    const double delta = r - dist;
    // Velocity of the disc's contact point (at -r n) relative to the wall's surface.
    const double len = w.length();
    const double ex = len > 0 ? (w.bx - w.ax) / len : 0, ey = len > 0 ? (w.by - w.ay) / len : 0;
    const double wvx = w.vx + w.surface_speed * ex, wvy = w.vy + w.surface_speed * ey;
    const double rvx = d.vx[i] - d.omega[i] * r * tx - wvx;
    const double rvy = d.vy[i] - d.omega[i] * r * ty - wvy;
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

}  // namespace

void wall_forces_share(NeighborList& L, const Discs& d, const std::vector<Wall>& walls, const ContactLaw& law,
                       double dt, DiscForce* forces, const ThreadSplit& split, std::size_t t) {
  auto& wc = L.walls;
  // The first contact at or after (wall w, disc i): contacts are in wall, then disc order.
  auto first_at = [&](std::size_t w, std::ptrdiff_t i) {
    std::size_t lo = 0, hi = wc.size();
    const std::pair<std::size_t, std::ptrdiff_t> key{w, i};
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (std::pair<std::size_t, std::ptrdiff_t>{wc.wall[mid], wc.disc[mid]} < key) lo = mid + 1; else hi = mid;
    }
    return lo;
  };
  // The contacts of thread t's own discs, wall by wall: every disc still adds its wall forces
  // in wall order, whatever the number of threads.
  for (std::size_t w = 0; w < walls.size(); ++w)
    contact_range(wc, d, walls, law, dt, forces, first_at(w, split.disc[t]), first_at(w, split.disc[t + 1]));
}

}  // namespace orogen
