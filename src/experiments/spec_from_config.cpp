#include "experiments/spec_from_config.hpp"

#include <fmt/format.h>

#include <numbers>

#include "config/config.hpp"
#include "world/world.hpp"

namespace orogen {

PackingSpec packing_spec(const Config& c) {
  PackingSpec p;
  p.kind = packing_kind_from_name(c.get_string("particles.packing"));
  p.length = c.get_float("layer.length");
  p.thickness = c.get_float("layer.thickness");
  p.d_min = c.get_float("particles.d_min");
  p.d_max = c.get_float("particles.d_max");
  p.seed = static_cast<std::uint64_t>(c.get_int("run.seed"));
  p.mu_wall = c.get_float("contact.mu_wall");
  if (p.d_min > p.d_max)
    throw config_error(c.source_of("particles.d_min"), "particles.d_min", fmt::format("{}", p.d_min),
                       fmt::format("must not exceed particles.d_max = {}", p.d_max));
  return p;
}

SettleSpec settle_spec(const Config& c) {
  SettleSpec s;
  s.drag = c.get_float("settle.drag");
  s.ke_threshold = c.get_float("settle.ke_threshold");
  s.max_time = c.get_float("settle.max_time");
  s.relax_time = c.get_float("settle.relax_time");
  s.mu = c.get_float("settle.mu");
  s.column_width_factor = c.get_float("layer.column_width_factor");
  return s;
}

void check_imposed_speed(const Config& c, const std::string& key) {
  const double v = c.get_float(key);
  const double kn = c.get_float("contact.kn");
  const double d_min = c.get_float("particles.d_min");
  const double m_min = std::numbers::pi * 0.25 * d_min * d_min;
  const double limit = stable_time_step(kn, 0.5 * m_min);
  const double dt = c.get_float("time.dt") > 0 ? c.get_float("time.dt") : c.get_float("time.dt_fraction") * limit;
  const double overlap = m_min / kn;
  if (dt > limit) return;  // apply_engine_config refuses the time step itself
  if (v * dt >= overlap)
    throw config_error(c.source_of(key), key, fmt::format("{}", v),
                       fmt::format("the boundary would move {:.3g} d per step, more than the gravitational contact "
                                   "overlap m g / k_n = {:.3g} d of the smallest disc (thesis eq. 4.3); "
                                   "use {} < {:.4g}, or a smaller time.dt",
                                   v * dt, overlap, key, overlap / dt));
}

}  // namespace orogen
