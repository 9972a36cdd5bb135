// Applies the engine sections of the configuration to a World.
#include <fmt/format.h>

#include "config/config.hpp"
#include "contact/normal_laws.hpp"
#include "experiments/experiment.hpp"
#include "experiments/time_step_config.hpp"

namespace orogen {

void apply_engine_config(const Config& c, World& w) {
  ContactLaw law = w.law();
  law.kn = c.get_float("contact.kn");
  law.ks = c.get_float("contact.ks_ratio") * law.kn;
  law.mu = c.get_float("contact.mu");
  law.normal_force = normal_law_index(c.get_string("contact.normal_force"));  // a name the schema allows
  const bool per_mass = c.get_string("contact.damping") == "per_mass";
  law.damping = per_mass ? NormalDamping::PerMass : NormalDamping::Restitution;
  law.restitution = c.get_float("contact.restitution");
  law.damping_rate = c.get_float("contact.damping_rate");
  bool calibrated = true;  // whether the restitution calibration holds for the normal law
  with_normal_law(law.normal_force, [&](auto normal) { calibrated = normal.restitution_damping; });
  if (!per_mass && !calibrated)
    throw config_error(c.sources_of({"contact.damping", "contact.normal_force"}), "contact.damping",
                       c.get_string("contact.damping"),
                       fmt::format("\"per_mass\" with contact.normal_force = \"{}\" (the restitution calibration "
                                   "is the clamped linear law's); give the dashpot as contact.damping_rate",
                                   c.get_string("contact.normal_force")));
  law.tangential_damping_ratio = c.get_float("contact.tangential_damping_ratio");
  law.rolling_friction = c.get_float("contact.rolling_friction");
  law.rolling_stiffness = c.get_float("contact.rolling_stiffness");
  w.set_contact_law(law);
  w.set_neighbor_skin(c.get_float("neighbor.skin"));
  w.set_sort_every(c.get_int32("neighbor.sort_every"));
  w.set_materials(c.materials());  // the experiment gives its discs their materials once settled
  const ConfigTimeStep step = config_time_step(c);
  if (step.given && step.dt > step.limit && step.k_bond > 0)
    throw config_error(c.sources_of({"time.dt", "contact.kn", "particles.d_min"}), "time.dt",
                       fmt::format("{}", step.dt),
                       fmt::format("must not exceed the stability limit 0.1 * 2 pi sqrt(m_min_eff / (k_n + k_bond)) = "
                                   "{:.6g}, where the stiffest bond of [materials] (bond_stiffness x k_n x "
                                   "bond_radius_factor x d_max) adds k_bond = {:.6g} to {}: lower time.dt (0 computes "
                                   "it) or a material's bond_stiffness",
                                   step.limit, step.k_bond, c.describe({"contact.kn", "particles.d_min"})));
  if (step.given && step.dt > step.limit)
    throw config_error(c.sources_of({"time.dt", "contact.kn", "particles.d_min"}), "time.dt",
                       fmt::format("{}", step.dt),
                       fmt::format("must not exceed the stability limit 0.1 * 2 pi sqrt(m_min_eff / k_n) = {:.6g} "
                                   "computed from {} (or use 0 to compute it)",
                                   step.limit, c.describe({"contact.kn", "particles.d_min"})));
  w.set_time_step(step.dt);
}

}  // namespace orogen
