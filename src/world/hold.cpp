#include "world/hold.hpp"

namespace orogen {

std::size_t hold_at_rest(World& w, std::span<const std::uint8_t> flags) {
  auto& d = w.discs;
  auto& c = w.clusters;
  constexpr auto kinematic = static_cast<std::uint8_t>(Motion::Kinematic);
  std::vector<std::uint8_t> cluster_held(c.size(), 0);
  for (std::size_t i = 0; i < d.size(); ++i)
    if (flags[i] && d.cluster[i] >= 0) cluster_held[static_cast<std::size_t>(d.cluster[i])] = 1;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (!cluster_held[k]) continue;
    c.motion[k] = kinematic;
    c.vx[k] = 0; c.vy[k] = 0; c.omega[k] = 0;
  }
  std::size_t held = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const bool hold = d.cluster[i] >= 0 ? cluster_held[static_cast<std::size_t>(d.cluster[i])] != 0 : flags[i] != 0;
    if (!hold) continue;
    d.motion[i] = kinematic;
    d.vx[i] = 0; d.vy[i] = 0; d.omega[i] = 0;
    ++held;
  }
  update_cluster_discs(c, d);
  w.invalidate_neighbors();
  return held;
}

}  // namespace orogen
