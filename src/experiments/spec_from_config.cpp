#include "experiments/spec_from_config.hpp"

#include <fmt/format.h>

#include <numbers>
#include <string_view>
#include <vector>

#include "config/config.hpp"
#include "experiments/time_step_config.hpp"
#include "world/world.hpp"

namespace orogen {

PackingSpec packing_spec(const Config& c) {
  PackingSpec p;
  p.kind = packing_kind_from_name(c.get_string("particles.packing"));
  p.placement = placement_from_name(c.get_string("particles.placement"));
  if (p.kind == PackingKind::Hexagonal && p.placement != Placement::Grid)
    throw config_error(c.source_of("particles.placement"), "particles.placement", c.get_string("particles.placement"),
                       "applies to the random packings; particles.packing = \"hexagonal\" is a lattice of equal "
                       "discs already (leave particles.placement at \"grid\")");
  p.length = c.get_float("layer.length");
  p.thickness = c.get_float("layer.thickness");
  p.d_min = c.get_float("particles.d_min");
  p.d_max = c.get_float("particles.d_max");
  p.seed = static_cast<std::uint64_t>(c.get_int("run.seed"));
  p.mu_wall = c.get_float("contact.mu_wall");
  if (p.d_min > p.d_max)
    throw config_error(c.sources_of({"particles.d_min", "particles.d_max"}), "particles.d_min",
                       fmt::format("{}", p.d_min),
                       fmt::format("must not exceed particles.d_max = {} ({})", p.d_max, c.source_of("particles.d_max")));
  return p;
}

void check_material_size(const Config& c, double length, double thickness,
                         const std::vector<std::string_view>& size_keys) {
  std::vector<std::string_view> keys = size_keys;
  keys.insert(keys.end(), {"particles.d_min", "particles.d_max"});
  const double d_min = c.get_float("particles.d_min"), d_max = c.get_float("particles.d_max");
  // Placed material is about 6% above the target and packs at most ~0.9 solid; discs of the mean
  // diameter. Written so that an overflow (inf) or NaN fails the test too.
  const double d_mean = 0.5 * (d_min + d_max);
  const double discs = length * thickness * 1.06 / (0.9 * 0.25 * std::numbers::pi * d_mean * d_mean);
  if (!(discs <= kMaxParticles))
    throw config_error(c.sources_of(keys), "", "",
                       fmt::format("the run would hold about {:.3g} discs ({:.4g} d x {:.4g} d of material), more "
                                   "than the limit of {:g} million; make the layer smaller or the discs larger. From {}",
                                   discs, length, thickness, kMaxParticles / 1e6, c.describe(keys)));
  // Surface columns are column_width_factor mean radii wide (a mean radius is at least d_min / 2).
  keys.push_back("layer.column_width_factor");
  const double columns = length / (c.get_float("layer.column_width_factor") * 0.5 * d_min);
  if (!(columns <= kMaxParticles))
    throw config_error(c.sources_of(keys), "layer.column_width_factor",
                       format_value(ConfigValue{c.get_float("layer.column_width_factor")}),
                       fmt::format("the surface would need about {:.3g} columns over {:.4g} d, more than the limit of "
                                   "{:g} million; use wider columns or a shorter layer. From {}",
                                   columns, length, kMaxParticles / 1e6, c.describe(keys)));
}

SettleSpec settle_spec(const Config& c) {
  SettleSpec s;
  s.drag = c.get_float("settle.drag");
  s.ke_threshold = c.get_float("settle.ke_threshold");
  s.max_time = c.get_float("settle.max_time");
  s.relax_time = c.get_float("settle.relax_time");
  s.mu = c.get_float("settle.mu");
  s.column_width_factor = c.get_float("layer.column_width_factor");
  s.adapt_threads = c.get_bool("run.adapt_threads");
  s.adapt_slice = c.get_float("run.adapt_slice");
  return s;
}

std::string imposed_speed_excess(const Config& c, const std::string& key) {
  const double v = c.get_float(key);
  const ConfigTimeStep step = config_time_step(c);
  const double dt = step.dt;
  const double overlap = step.m_min / c.get_float("contact.kn");
  if (dt > step.limit) return {};  // apply_engine_config refuses the time step itself
  if (v * dt < overlap) return {};
  const std::vector<std::string_view> keys = {key, "contact.kn", "particles.d_min", "time.dt", "time.dt_fraction"};
  return fmt::format("the boundary would move {:.3g} d per step, more than the gravitational contact "
                     "overlap m g / k_n = {:.3g} d of the smallest disc (thesis eq. 4.3); "
                     "use {} < {:.4g}, or a smaller time step (time.dt, time.dt_fraction) or a "
                     "stiffer contact.kn; the bound comes from {}",
                     v * dt, overlap, key, overlap / dt, c.describe(keys));
}

void check_imposed_speed(const Config& c, const std::string& key) {
  const std::string excess = imposed_speed_excess(c, key);
  if (!excess.empty())
    throw config_error(c.sources_of({key, "contact.kn", "particles.d_min", "time.dt", "time.dt_fraction"}), key,
                       fmt::format("{}", c.get_float(key)), excess);
}

std::ptrdiff_t material_named_by(const Config& c, const std::string& key) {
  const std::string& name = c.get_string(key);
  if (name.empty()) return -1;
  std::string names;
  for (std::size_t k = 0; k < c.materials().size(); ++k) {
    if (c.materials().list[k].name == name) return static_cast<std::ptrdiff_t>(k);
    names += (names.empty() ? "" : ", ") + c.materials().list[k].name;
  }
  throw config_error(c.source_of(key), key, "\"" + name + "\"",
                     "a name of [materials] (" + (names.empty() ? std::string("none defined") : names) + "), or empty");
}

BaseWeakening base_weakening(const Config& c, std::string_view section) {
  const std::string key = fmt::format("{}.basal_weakening", section);
  const BaseWeakening b{c.get_float(key), c.get_float(key + "_distance")};
  if (b.fraction > 0 && c.materials().empty())
    throw config_error(c.sources_of({key}), key, fmt::format("{}", b.fraction),
                       "0 without [materials.NAME]: the base weakens with the slip each disc accumulates, "
                       "which a world of named materials keeps (docs/materials.md); define the layer's "
                       "material, or set 0");
  return b;
}

std::vector<std::string> config_warnings(const Config& c) {
  std::vector<std::string> out;
  if (c.get_string("run.experiment") == "singly_vergent" && c.get_string("singly.speed_bound") == "warn") {
    const std::string excess = imposed_speed_excess(c, "singly.speed");
    if (!excess.empty())
      out.push_back(fmt::format("singly.speed = {}: {}. For the backstop this is a quasi-static rule, not a "
                                "stability limit (docs/model.md); singly.speed_bound = \"off\" silences this, "
                                "\"refuse\" refuses it",
                                c.get_float("singly.speed"), excess));
  }
  return out;
}

}  // namespace orogen
