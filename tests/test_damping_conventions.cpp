// The two conventions of the normal dashpot (contact.damping) and of its sign (contact.normal_force)
// against the closed-form restitution of a head-on binary collision and of a wall bounce
// (docs/model.md, "Contact law"): per unit effective mass (LAMMPS's gamma_n) the wall, whose
// m_eff is the whole disc mass, is damped sqrt(2) more strongly (in zeta) than a pair of equal
// discs; from restitution both rebound with the configured coefficient.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/normal_laws.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

constexpr double kKn = 1e4;
constexpr double kMass = std::numbers::pi * 0.25;  // a disc of radius 0.5

World empty_world(std::string_view normal_law, bool per_mass, double rate_or_e) {
  World w;
  inside(w).body.gy = 0;
  inside(w).law.kn = kKn;
  inside(w).law.ks = 0.5 * kKn;
  inside(w).law.mu = 0.3;
  inside(w).law.normal_force = normal_law_index(normal_law);
  inside(w).law.damping = per_mass ? NormalDamping::PerMass : NormalDamping::Restitution;
  (per_mass ? inside(w).law.damping_rate : inside(w).law.restitution) = rate_or_e;
  return w;
}

// Restitution of two equal discs meeting head-on at unit closing speed.
double pair_restitution(World w) {
  w.add_disc(0.0, 0.0, 0.5);
  w.add_disc(1.1, 0.0, 0.5);
  inside(w).discs.vx[0] = 0.5;
  inside(w).discs.vx[1] = -0.5;
  inside(w).dt = w.stable_dt() / 100;  // resolve the contact finely (the analytic case)
  while (w.time() < 0.4) w.advance();
  return w.discs().vx[1] - w.discs().vx[0];
}

// Restitution of a disc falling at unit speed onto a fixed smooth wall.
double wall_restitution(World w) {
  inside(w).walls = {testing::wall(-5, 0, 5, 0)};
  w.add_disc(0.0, 0.6, 0.5);
  inside(w).discs.vy[0] = -1.0;
  inside(w).dt = w.stable_dt() / 100;
  while (w.time() < 0.4) w.advance();
  return w.discs().vy[0];
}

// Closed forms (MODEL §3): the clamped dashpot lets go before delta = 0
// (restitution_for_damping_ratio); the pulling one after half a damped period.
double pull_restitution(double zeta) { return std::exp(-std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta)); }
double zeta_per_mass(double rate, double m_eff) { return 0.5 * rate * std::sqrt(m_eff / kKn); }

TEST(DampingConventions, PerMassPairAndWallMatchTheClosedForms) {
  const double m_pair = 0.5 * kMass, m_wall = kMass;
  for (const double zeta_pair : {0.05, 0.2, 0.5}) {
    const double rate = 2 * zeta_pair * std::sqrt(kKn / m_pair);
    const double zeta_wall = zeta_per_mass(rate, m_wall);
    EXPECT_NEAR(zeta_wall, std::sqrt(2.0) * zeta_pair, 1e-12);
    // The clamped law (Orogen's default normal force).
    const double e_pair = restitution_for_damping_ratio(zeta_pair);
    const double e_wall = restitution_for_damping_ratio(zeta_wall);
    EXPECT_NEAR(pair_restitution(empty_world("linear", true, rate)), e_pair, 0.01 * e_pair) << zeta_pair;
    EXPECT_NEAR(wall_restitution(empty_world("linear", true, rate)), e_wall, 0.01 * e_wall) << zeta_pair;
    // The dashpot that may pull (LAMMPS gran/hooke/history): more dissipative at the same zeta.
    const double p_pair = pull_restitution(zeta_pair), p_wall = pull_restitution(zeta_wall);
    EXPECT_LT(p_pair, e_pair);
    EXPECT_NEAR(pair_restitution(empty_world("linear_pull", true, rate)), p_pair, 0.01 * p_pair) << zeta_pair;
    EXPECT_NEAR(wall_restitution(empty_world("linear_pull", true, rate)), p_wall, 0.01 * p_wall) << zeta_pair;
  }
}

TEST(DampingConventions, FromRestitutionPairsAndWallsReboundAlike) {
  for (const double e : {0.2, 0.5, 0.9}) {
    EXPECT_NEAR(pair_restitution(empty_world("linear", false, e)), e, 0.01 * e) << e;
    EXPECT_NEAR(wall_restitution(empty_world("linear", false, e)), e, 0.01 * e) << e;
  }
}

TEST(DampingConventions, ThePullingDashpotPullsAndTheDefaultNeverDoes) {
  // Separating fast from a small overlap: k_n delta < gamma_n v_n.
  const double delta = 1e-4, vn = 1.0, gn = 20.0;
  EXPECT_EQ(LinearNormal::force(kKn, delta, gn, vn, 0.25), 0.0);
  EXPECT_DOUBLE_EQ(LinearPullNormal::force(kKn, delta, gn, vn, 0.25), kKn * delta - gn * vn);
  EXPECT_LT(LinearPullNormal::force(kKn, delta, gn, vn, 0.25), 0.0);
  // The Coulomb limit of a pulling contact is mu |F_n|, as in LAMMPS.
  EXPECT_DOUBLE_EQ(LinearPullNormal::load(-3.0), 3.0);
}

}  // namespace
}  // namespace orogen
