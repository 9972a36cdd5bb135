#pragma once
// Small worlds for the physics tests.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "world/world.hpp"

namespace orogen::testing {

inline Wall wall(double ax, double ay, double bx, double by, WallFriction f = WallFriction::Smooth, double mu = 0) {
  Wall w;
  w.ax = ax; w.ay = ay; w.bx = bx; w.by = by;
  w.friction = f;
  w.mu = mu;
  return w;
}

// Keeps in `out` a copy of each step's summed disc forces as integration receives them (it
// zeroes them after use, so World::scratch holds zeros between steps): an AfterForces hook.
inline void record_step_forces(World& w, std::vector<DiscForce>& out) {
  w.hooks().add(Stage::AfterForces, "test.record_forces", [&out](World& world) { out = world.scratch().forces; });
}

// Elastic energy stored in the disc-disc and disc-wall normal springs.
inline double spring_energy(const World& w) {
  double e = 0;
  const auto& d = w.discs();
  for (std::size_t p = 0; p < w.neighbors().size(); ++p) {
    const auto i = w.neighbors().first[p], j = w.neighbors().second[p];
    const double delta = d.radius[i] + d.radius[j] - std::hypot(d.x[j] - d.x[i], d.y[j] - d.y[i]);
    if (delta > 0) e += 0.5 * w.law().kn * delta * delta;
  }
  for (std::size_t k = 0; k < w.contacts().walls.size(); ++k) {
    const auto i = w.contacts().walls.disc[k];
    double cx, cy;
    const double dist = std::sqrt(closest_point_on_segment(w.walls()[w.contacts().walls.wall[k]], d.x[i], d.y[i], cx, cy));
    const double delta = d.radius[i] - dist;
    if (delta > 0) e += 0.5 * w.law().kn * delta * delta;
  }
  return e;
}

// A cluster of three touching discs of radius 0.5, its lower two centred at (x -+ 0.5, y), all
// moving at vx; the discs' indices.
inline std::array<std::size_t, 3> add_triangle_cluster(World& w, double x, double y, double vx = 0) {
  const std::array<std::size_t, 3> idx = {w.add_disc(x - 0.5, y, 0.5), w.add_disc(x + 0.5, y, 0.5),
                                          w.add_disc(x, y + 0.866025403784, 0.5)};
  for (const auto i : idx) w.set_disc_velocity(i, vx, 0, 0);
  w.add_cluster(idx);
  return idx;
}

}  // namespace orogen::testing
