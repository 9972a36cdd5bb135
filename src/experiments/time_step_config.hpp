#pragma once
// The time step a configuration gives, computed in this one place: the stability limit
// (MODEL §3, stable_time_step) for the smallest disc the configuration can make (a disc of
// particles.d_min: the world may still be empty when it is needed), and the step itself,
// time.dt or, when that is 0, time.dt_fraction of the limit.
namespace orogen {

class Config;
struct World;

struct ConfigTimeStep {
  double m_min = 0;      // mass of the smallest disc, pi d_min^2 / 4 (unit density)
  double k_bond = 0;     // stiffness of the stiffest bond the materials can make (0: no bonds)
  double limit = 0;      // 0.1 * 2 pi sqrt(m_min_eff / (k_n + k_bond)), m_min_eff = m_min / 2
  double dt = 0;         // the step the run takes
  bool given = false;    // dt came from time.dt (checked against the limit), not time.dt_fraction
};

ConfigTimeStep config_time_step(const Config& config);

// Refuses (ConfigError naming particles.d_min) a world whose lightest disc makes the time step
// unstable: discs built outside the experiment (a Python setup function) below particles.d_min.
void check_world_time_step(const Config& config, const World& world);

}  // namespace orogen
