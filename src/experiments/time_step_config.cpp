#include "experiments/time_step_config.hpp"

#include <numbers>

#include "config/config.hpp"
#include "world/world.hpp"

namespace orogen {

ConfigTimeStep config_time_step(const Config& c) {
  ConfigTimeStep t;
  const double d_min = c.get_float("particles.d_min");
  t.m_min = std::numbers::pi * 0.25 * d_min * d_min;
  t.limit = stable_time_step(c.get_float("contact.kn"), 0.5 * t.m_min);
  const double dt = c.get_float("time.dt");
  t.given = dt > 0;
  t.dt = t.given ? dt : c.get_float("time.dt_fraction") * t.limit;
  return t;
}

}  // namespace orogen
