#pragma once
// The linear spring-dashpot normal force, in its two conventions (MODEL §3, "Contact law"):
// `linear` never pulls (Orogen's default and the thesis's law: the force is clamped at zero),
// `linear_pull` lets the dashpot pull while the discs overlap, as LAMMPS's gran/hooke/history
// does (no limit_damping). A normal law is a type with
//   name                          its value of contact.normal_force
//   force(kn, delta, gn, vn, r_eff)  the normal force (inline, branch-free); r_eff is the
//                                 contact's effective radius r_i r_j / (r_i + r_j), a disc's
//                                 radius against a wall (for a Hertzian law; unused values cost
//                                 nothing once inlined)
//   elastic(kn, delta, r_eff)     the elastic part alone (the biaxial servo measures it)
//   load(fn)                      the normal load that the Coulomb limit mu * load caps
//   restitution_damping           whether contact.damping = "restitution" is calibrated for it
#include <cmath>

#include "contact/law_kernels.hpp"

namespace orogen {

struct LinearNormal {
  static constexpr const char* name = "linear";
  static constexpr const char* doc = "k_n delta - gamma_n v_n, clamped at zero (never pulls)";
  static constexpr bool restitution_damping = true;
  static double force(double kn, double delta, double gn, double vn, double /*r_eff*/) {
    const double fn = spring_dashpot(kn, delta, gn, vn);
    return fn < 0 ? 0.0 : fn;
  }
  static double elastic(double kn, double delta, double /*r_eff*/) { return kn * delta; }
  static double load(double fn) { return fn; }
};

struct LinearPullNormal {
  static constexpr const char* name = "linear_pull";
  static constexpr const char* doc = "k_n delta - gamma_n v_n, may pull while overlapping (LAMMPS gran/hooke/history)";
  // The restitution calibration assumes the clamp; give the dashpot per unit mass instead.
  static constexpr bool restitution_damping = false;
  static double force(double kn, double delta, double gn, double vn, double /*r_eff*/) {
    return spring_dashpot(kn, delta, gn, vn);
  }
  static double elastic(double kn, double delta, double /*r_eff*/) { return kn * delta; }
  // As LAMMPS: the Coulomb limit is mu |F_n|, also while the dashpot pulls.
  static double load(double fn) { return std::fabs(fn); }
};

}  // namespace orogen
