#pragma once
// The Hertzian normal force (contact.normal_force = "hertz"), as LAMMPS's gran/hertz/history:
// the linear spring-dashpot scaled by the contact radius sqrt(r_eff delta),
//   F = sqrt(r_eff delta) (k_n delta - gamma_n v_n), clamped at zero,
// so its spring is k_n sqrt(r_eff) delta^{3/2} (k_n then a modulus, force per length^2, not a
// stiffness). Hertz's law is that of 3D spheres; for discs (2D cylinders) the exact elastic law
// is nearly linear with a logarithmic factor, so this is "Hertz-like": the 3/2 power law the
// DEM codes use, chosen for comparison with them (docs/model.md). With no dashpot a head-on
// collision lasts t_c = 2.9432 delta_max / v_0, delta_max = (5 m_eff v_0^2 / (4 k_n sqrt(r_eff)))^{2/5}
// (tests/test_hertz_normal.cpp). The restitution calibration of ContactLaw (linear) does not
// hold for it: give the dashpot per unit mass (contact.damping = "per_mass").
#include <cmath>

#include "contact/law_kernels.hpp"

namespace orogen {

struct HertzNormal {
  static constexpr const char* name = "hertz";
  static constexpr const char* doc =
      "sqrt(r_eff delta) (k_n delta - gamma_n v_n), clamped at zero (LAMMPS gran/hertz/history; needs "
      "contact.damping = \"per_mass\")";
  static constexpr bool restitution_damping = false;
  // The kernels evaluate the law for pairs apart too (and mask the result): no sqrt of a
  // negative overlap there.
  static double contact_radius(double delta, double r_eff) { return std::sqrt(r_eff * (delta > 0 ? delta : 0.0)); }
  static double force(double kn, double delta, double gn, double vn, double r_eff) {
    const double fn = contact_radius(delta, r_eff) * spring_dashpot(kn, delta, gn, vn);
    return fn < 0 ? 0.0 : fn;
  }
  static double elastic(double kn, double delta, double r_eff) { return contact_radius(delta, r_eff) * kn * delta; }
  static double load(double fn) { return fn; }
};

}  // namespace orogen
