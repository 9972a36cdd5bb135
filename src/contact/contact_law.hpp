#pragma once
// The parameters of the contact law (MODEL §3) and the calibration of its normal dashpot. The
// law itself is written once: contact/law_kernels.hpp (its pieces), contact/normal_laws.hpp
// (the registered normal forces), contact/contact_block.hpp (a disc pair) and
// boundary/wall_contact_law.hpp (a disc and a wall).
#include <cmath>
#include <cstddef>
#include <vector>

namespace orogen {

// How the normal dashpot is set. Restitution: gamma_n = 2 zeta sqrt(k_n m_eff) per pair, with
// zeta chosen so that a head-on collision rebounds with the configured coefficient. PerMass:
// gamma_n = m_eff * rate, the convention of LAMMPS gran/hooke (LAMMPS's gamma_n; the
// benchmark uses it): a wall contact, whose m_eff is the disc's whole mass, is then damped
// more strongly than a pair of equal discs (m_eff half a disc's mass).
enum class NormalDamping { Restitution, PerMass };

struct ContactLaw {
  std::size_t normal_force = 0;  // index into NormalLaws (contact/normal_laws.hpp); 0 = linear
  double kn = 1e4;            // normal stiffness, m g / d
  double ks = 5e3;            // tangential stiffness
  double mu = 0.3;            // Coulomb friction coefficient
  NormalDamping damping = NormalDamping::Restitution;
  double restitution = 0.2;   // e_n, for NormalDamping::Restitution
  double damping_rate = 0.0;  // gamma_n / m_eff, for NormalDamping::PerMass
  double tangential_damping_ratio = 0.0;  // gamma_s = ratio * gamma_n
  // Rolling resistance (docs/model.md "Rolling resistance"): an elastic-plastic spring on the
  // pair's relative rotation, its moment capped at rolling_friction r_eff F_n. 0: none (the
  // thesis's law; the pair loops then keep no rolling history at all).
  double rolling_friction = 0.0;   // mu_r
  double rolling_stiffness = 1.0;  // k_r in units of k_s r_eff^2 (at most 2: docs/model.md, the time step)

  // Normal dashpot coefficient for a pair of effective mass m_eff integrated with step dt.
  // For Restitution the damping ratio is calibrated to the discrete integrator (see
  // discrete_damping_ratio), so a collision rebounds with e at the time step actually used.
  double gamma_n(double m_eff, double dt) const;
  // Fills the damping table for effective masses in [m_lo, m_hi] at step dt (gamma_n fills
  // it lazily otherwise; call this before calling gamma_n from several threads).
  void prepare_damping(double m_lo, double m_hi, double dt) const;

 private:
  double zeta_entry(int k) const;
  mutable double table_e_ = -1;               // restitution the table was built for
  mutable std::vector<double> zeta_table_;    // damping ratio against omega0 dt
};

// Damping ratio zeta of the no-pull spring-dashpot that gives restitution e in a head-on
// collision. The force is clipped at zero, so the discs part when k delta + gamma d(delta)/dt
// reaches zero (slightly before delta = 0); the inversion accounts for that exactly.
// Valid for e in [kMinRestitution, 1]: a dashpot that never pulls cannot rebound slower.
double damping_ratio_for_restitution(double e);
constexpr double kMaxDampingRatio = 0.999;
constexpr double kMinRestitution = 0.14;

// Restitution and contact duration of the no-pull law for damping ratio zeta and natural
// frequency omega0 = sqrt(k_n / m_eff) (closed form of the damped oscillator).
double restitution_for_damping_ratio(double zeta);
double contact_duration(double zeta, double omega0);

// The same inversion for the discrete semi-implicit Euler scheme at omega0 * dt: the
// restitution of a simulated 1-D collision. At the stable limit (omega0 dt ~ 0.6) the
// continuous formula would give a collision far more dissipative than asked for.
double discrete_restitution(double zeta, double omega0_dt);
double discrete_damping_ratio(double e, double omega0_dt);

}  // namespace orogen
