// The Hertzian normal law (contact.normal_force = "hertz", src/contact/normal_hertz.hpp)
// against the closed forms of a head-on collision with F = k' delta^{3/2}, k' = k_n sqrt(r_eff):
// undamped, the discs rebound with their speed (restitution 1) after
//   t_c = 2.9432 delta_max / v0,  delta_max = (5 m_eff v0^2 / (4 k'))^{2/5}
// (2 delta_max / v0 times the integral of (1 - x^{5/2})^{-1/2} over (0, 1), 1.47163). Discs are
// 2D here: the 3/2 power is the 3D spheres' law, taken as the DEM codes take it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/normal_laws.hpp"
#include "world/world.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

constexpr double kLinearKn = 1e4;
constexpr double kDiscMass = std::numbers::pi * 0.25;  // a disc of radius 0.5

struct Collision {
  double restitution = 0, contact_time = 0, max_overlap = 0;
};

// Two equal discs meeting head-on at closing speed v0, per-unit-mass dashpot `rate`.
Collision collide(double v0, double rate) {
  World w;
  inside(w).body.gy = 0;
  inside(w).law.kn = kLinearKn;
  inside(w).law.ks = 0.5 * kLinearKn;
  inside(w).law.mu = 0.3;
  inside(w).law.normal_force = normal_law_index("hertz");
  inside(w).law.damping = NormalDamping::PerMass;
  inside(w).law.damping_rate = rate;
  w.add_disc(0.0, 0.0, 0.5);
  w.add_disc(1.05, 0.0, 0.5);
  inside(w).discs.vx[0] = 0.5 * v0;
  inside(w).discs.vx[1] = -0.5 * v0;
  inside(w).dt = 2e-6;  // t_c / dt of some ten thousand: the contact resolved finely
  Collision c;
  double t_in = -1, t_out = -1;
  while (w.time() < 0.4 && t_out < 0) {
    w.advance();
    const double overlap = 1.0 - (w.discs().x[1] - w.discs().x[0]);
    c.max_overlap = std::max(c.max_overlap, overlap);
    if (overlap > 0 && t_in < 0) t_in = w.time();
    if (overlap <= 0 && t_in >= 0) t_out = w.time();
  }
  c.contact_time = t_out - t_in;
  c.restitution = (w.discs().vx[1] - w.discs().vx[0]) / v0;
  return c;
}

TEST(HertzNormal, IsRegisteredAndNeedsThePerMassDashpot) {
  ASSERT_LT(normal_law_index("hertz"), kNormalLawCount);
  bool calibrated = true;
  with_normal_law(normal_law_index("hertz"), [&](auto law) { calibrated = law.restitution_damping; });
  EXPECT_FALSE(calibrated);
}

TEST(HertzNormal, UndampedCollisionMatchesTheHertzContactTimeAndRebounds) {
  const double m_eff = 0.5 * kDiscMass, r_eff = 0.25;
  const double k = kLinearKn * std::sqrt(r_eff);
  for (const double v0 : {0.2, 1.0}) {
    const Collision c = collide(v0, 0.0);
    const double delta_max = std::pow(5 * m_eff * v0 * v0 / (4 * k), 0.4);
    const double t_c = 2.94326 * delta_max / v0;
    EXPECT_NEAR(c.max_overlap, delta_max, 2e-3 * delta_max) << "v0 " << v0;
    EXPECT_NEAR(c.contact_time, t_c, 2e-3 * t_c) << "v0 " << v0;
    EXPECT_NEAR(c.restitution, 1.0, 1e-3) << "v0 " << v0;
    // Unlike a linear spring, the contact time falls with the speed, as v0^{-1/5}.
  }
  const double ratio = collide(0.2, 0.0).contact_time / collide(1.0, 0.0).contact_time;
  EXPECT_NEAR(ratio, std::pow(5.0, 0.2), 5e-3);
}

TEST(HertzNormal, DashpotLowersTheRestitution) {
  const double e_light = collide(1.0, 5.0).restitution, e_heavy = collide(1.0, 50.0).restitution;
  EXPECT_LT(e_light, 1.0);
  EXPECT_LT(e_heavy, e_light);
  EXPECT_GT(e_heavy, 0.0);
}

}  // namespace
}  // namespace orogen
