#include "experiments/time_step_config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

#include "config/config.hpp"
#include "world/world.hpp"

namespace orogen {

ConfigTimeStep config_time_step(const Config& c) {
  ConfigTimeStep t;
  const double d_min = c.get_float("particles.d_min");
  t.m_min = std::numbers::pi * 0.25 * d_min * d_min;
  // A bond acts beside the contact: the stiffest bond a material can make (on the largest discs:
  // width 2 lambda r) adds to k_n.
  double k_bond = 0;
  for (const auto& m : c.materials().list)
    if (m.bond.bonds())
      k_bond = std::max(k_bond, m.bond.stiffness * c.get_float("contact.kn") * m.bond.radius_factor *
                                    c.get_float("particles.d_max"));
  t.k_bond = k_bond;
  t.limit = stable_time_step(c.get_float("contact.kn") + k_bond, 0.5 * t.m_min);
  const double dt = c.get_float("time.dt");
  t.given = dt > 0;
  t.dt = t.given ? dt : c.get_float("time.dt_fraction") * t.limit;
  return t;
}

void check_world_time_step(const Config& c, const World& w) {
  if (w.dt() <= w.stable_dt()) return;
  const auto& r = w.discs().radius;
  const double d_small = 2.0 * *std::min_element(r.begin(), r.end());
  throw config_error(c.sources_of({"particles.d_min", "time.dt"}), "particles.d_min",
                     fmt::format("{}", c.get_float("particles.d_min")),
                     fmt::format("the setup built discs down to diameter {:.6g}, for which the time step dt = {:.6g} "
                                 "exceeds the stability limit {:.6g}: set particles.d_min to at most {:.6g} (the "
                                 "time step follows it) or give a smaller time.dt; from {}",
                                 d_small, w.dt(), w.stable_dt(), d_small, c.describe({"particles.d_min", "time.dt"})));
}

}  // namespace orogen
