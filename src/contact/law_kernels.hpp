#pragma once
// The pieces of the contact law (MODEL §3), written once, without branches, as inline
// functions of plain doubles: the pair kernel (contact/contact_block.hpp), the wall law
// (boundary/wall_contact_law.hpp), the analyses and the tests are all built from these, so
// they apply bitwise the same law. No branch: the pair kernel runs them in the lanes of a
// vector loop. The normal force itself is a registered law (contact/normal_laws.hpp).
#include <cmath>

namespace orogen {

// Linear spring-dashpot normal force: k_n delta minus the dashpot gamma_n v_n (v_n > 0 when
// separating). May be negative (the dashpot pulling); a law that forbids it clamps after.
inline double spring_dashpot(double kn, double delta, double gn, double vn) { return kn * delta - gn * vn; }

// Tangential force and history of one contact after one step, and whether the Coulomb limit
// held it.
struct Tangential {
  double ft;  // force along t
  double xi;  // history after the step
  bool slip;  // |ft| reached the limit
};

// Tangential spring on the accumulated displacement xi (advanced by v_t dt), plus a dashpot
// gamma_s v_t, capped at the Coulomb limit mu F_n; on the limit the spring is set where it
// gives the capped force (so the history never stores more than the limit).
inline Tangential tangential_spring(double xi_old, double vt, double dt, double ks, double gs, double limit) {
  const double xi = xi_old + vt * dt;
  const double ft = -ks * xi - gs * vt;
  const bool slip = std::fabs(ft) > limit;
  const double ft_limit = std::copysign(limit, ft);
  const double xi_limit = -ft_limit / ks;  // computed unconditionally: no branch to vectorise
  return {slip ? ft_limit : ft, slip ? xi_limit : xi, slip};
}

// Viscous traction gamma v_t (thesis eq. 4.1), capped at the Coulomb limit; keeps no history.
inline Tangential viscous_traction(double gamma, double vt, double limit, double xi_old) {
  const double ft = -gamma * vt;
  const bool slip = std::fabs(ft) > limit;
  return {slip ? std::copysign(limit, ft) : ft, xi_old, slip};
}

}  // namespace orogen
