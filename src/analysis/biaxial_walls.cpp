#include "analysis/biaxial_walls.hpp"

#include <cmath>

#include "contact/normal_laws.hpp"

namespace orogen {
namespace {

template <class Normal>
void add_elastic_forces(const World& w, std::vector<WallForce>& out) {
  const auto& d = w.discs();
  w.for_each_wall_contact([&](const WallContactView& k) {
    const auto i = k.disc;
    if (i >= d.size()) return;  // list not rebuilt yet after a removal
    const Wall& wall = w.walls()[k.wall];
    if (!wall.enabled) return;
    double cx, cy;
    const double dist2 = closest_point_on_segment(wall, d.x[i], d.y[i], cx, cy);
    const double r = d.radius[i];
    if (dist2 >= r * r || dist2 == 0.0) return;
    const double dist = std::sqrt(dist2);
    // The elastic part of the contact law's normal force (no dashpot: the servo's stress).
    const double fn = Normal::elastic(w.law().kn, r - dist, r);
    // The disc is pushed along (disc - contact point); the wall the opposite way.
    out[k.wall].fx -= fn * (d.x[i] - cx) / dist;
    out[k.wall].fy -= fn * (d.y[i] - cy) / dist;
  });
}

}  // namespace

std::vector<WallForce> elastic_wall_forces(const World& w) {
  std::vector<WallForce> out(w.walls().size());
  with_normal_law(w.law().normal_force, [&](auto normal) { add_elastic_forces<decltype(normal)>(w, out); });
  return out;
}

}  // namespace orogen
