#pragma once
// The disc-disc contact law (MODEL §3): linear spring-dashpot normal force without pull,
// tangential spring on the accumulated tangential displacement with a Coulomb limit.
#include <cmath>
#include <vector>

namespace orogen {

// How the normal dashpot is set. Restitution: gamma_n = 2 zeta sqrt(k_n m_eff) per pair, with
// zeta chosen so that a head-on collision rebounds with the configured coefficient. PerMass:
// gamma_n = m_eff * rate, the convention of LAMMPS gran/hooke (used by the benchmark).
enum class NormalDamping { Restitution, PerMass };

struct ContactLaw {
  double kn = 1e4;            // normal stiffness, m g / d
  double ks = 5e3;            // tangential stiffness
  double mu = 0.3;            // Coulomb friction coefficient
  NormalDamping damping = NormalDamping::Restitution;
  double restitution = 0.2;   // e_n, for NormalDamping::Restitution
  double damping_rate = 0.0;  // gamma_n / m_eff, for NormalDamping::PerMass
  double tangential_damping_ratio = 0.0;  // gamma_s = ratio * gamma_n

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

// Per-pair result of the contact kernel.
struct PairForce {
  double fx = 0, fy = 0;  // force on the second disc (the first feels minus this)
  double ft = 0;          // tangential force component (for the torques -r_i ft, -r_j ft)
  double fn = 0;          // normal force component (along n, from i to j)
  bool at_limit = false;  // the tangential force sat on the Coulomb limit
};

// Computes the force between discs i and j given their relative geometry and kinematics.
// n points from i to j; xi is the tangential spring history (updated in place).
// Returns false (and zeroes xi) when the discs do not touch.
inline bool contact_force(double dx, double dy, double ri, double rj, double dvx, double dvy,
                          double wi, double wj, double kn, double ks, double mu, double gn,
                          double gs, double dt, double& xi, PairForce& out) {
  const double dist2 = dx * dx + dy * dy;
  const double rsum = ri + rj;
  if (dist2 >= rsum * rsum) {
    xi = 0;
    return false;
  }
  const double dist = std::sqrt(dist2);
  const double inv = 1.0 / dist;
  const double nx = dx * inv, ny = dy * inv;
  const double tx = -ny, ty = nx;
  const double delta = rsum - dist;
  // Relative velocity of j's contact point with respect to i's.
  const double rot = wi * ri + wj * rj;
  const double vn = dvx * nx + dvy * ny;        // > 0 when separating
  const double vt = dvx * tx + dvy * ty - rot;  // sliding along t
  double fn = kn * delta - gn * vn;
  if (fn < 0) fn = 0;
  xi += vt * dt;
  double ft = -ks * xi - gs * vt;
  const double limit = mu * fn;
  out.at_limit = std::fabs(ft) > limit;
  if (out.at_limit) {
    ft = std::copysign(limit, ft);
    xi = -ft / ks;  // the spring sits on the Coulomb limit
  }
  out.fn = fn;
  out.fx = fn * nx + ft * tx;
  out.fy = fn * ny + ft * ty;
  out.ft = ft;
  return true;
}

}  // namespace orogen
