// Two discs colliding head-on: restitution and contact duration against the closed-form
// no-pull spring-dashpot (MODEL §3).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "world/world.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

struct CollisionResult {
  double restitution = 0, duration = 0;
};

CollisionResult collide(double e, double v0) {
  World w;
  inside(w).body.gy = 0;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.restitution = e;
  inside(w).law.mu = 0.3;
  w.add_disc(0.0, 0.0, 0.5);
  w.add_disc(1.2, 0.0, 0.5);
  inside(w).discs.vx[0] = v0 / 2;
  inside(w).discs.vx[1] = -v0 / 2;
  inside(w).dt = w.stable_dt() / 100;  // resolve the contact finely (the analytic case)
  double t_start = -1, t_end = -1;
  std::vector<DiscForce> forces;
  testing::record_step_forces(w, forces);
  for (int s = 0; s < 200000 && t_end < 0; ++s) {
    w.advance();
    const double gap = w.discs().x[1] - w.discs().x[0] - 1.0;
    const bool pushing = std::fabs(forces[0].fx) > 0;
    if (pushing && t_start < 0) t_start = w.time() - w.dt();
    if (t_start >= 0 && !pushing && gap < 0.2) t_end = w.time() - w.dt();
  }
  const double v_after = w.discs().vx[1] - w.discs().vx[0];
  return {v_after / v0, t_end - t_start};
}

TEST(Collision, RestitutionMatchesConfiguredCoefficient) {
  for (double e : {0.2, 0.5, 0.9}) {
    const auto r = collide(e, 1.0);
    EXPECT_NEAR(r.restitution, e, 0.01 * e) << "e = " << e;
  }
}

TEST(Collision, DurationMatchesDampedOscillator) {
  for (double e : {0.2, 0.5, 0.9}) {
    const auto r = collide(e, 1.0);
    const double m_eff = 0.5 * M_PI * 0.25;
    const double expected = contact_duration(damping_ratio_for_restitution(e), std::sqrt(1e4 / m_eff));
    EXPECT_NEAR(r.duration, expected, 0.02 * expected) << "e = " << e;
  }
}

TEST(Collision, RestitutionInversionRoundTrips) {
  for (double e : {0.14, 0.2, 0.5, 0.9, 0.99}) {
    EXPECT_NEAR(restitution_for_damping_ratio(damping_ratio_for_restitution(e)), e, 1e-9);
  }
  EXPECT_DOUBLE_EQ(damping_ratio_for_restitution(1.0), 0.0);
  EXPECT_THROW(damping_ratio_for_restitution(0.1), std::invalid_argument);
}

}  // namespace
}  // namespace orogen
