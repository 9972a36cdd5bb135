// The tangential spring with its Coulomb limit, and the life of the contact history.
#include <gtest/gtest.h>

#include "contact/contact_block.hpp"
#include "contact/normal_laws.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

// The pair kernel (linear law, no dashpot) on one contact; xi is the history, updated in place.
ContactLane pair_contact(double dx, double dy, double dvx, double dvy, double kn, double ks, double mu, double dt,
                         double& xi) {
  const ContactLane c = contact_lane<LinearNormal>(dx, dy, 0.5, 0.5, dvx, dvy, 0, 0, 0, 0, xi, kn, ks, mu, dt);
  xi = c.xi;
  return c;
}

// Drives a contact with a steady sliding velocity and returns the tangential force.
TEST(Coulomb, SpringSticksBelowTheLimitAndSlipsOnIt) {
  const double kn = 1e4, ks = 5e3, mu = 0.3, dt = 1e-3, overlap = 0.01;
  const double fn = kn * overlap;
  double xi = 0;
  ContactLane f{};
  // Sliding at speed v along t accumulates xi = v t; the force is -ks xi until mu fn.
  const double v = 0.1;
  int stuck_steps = 0;
  for (int s = 0; s < 200; ++s) {
    f = pair_contact(1.0 - overlap, 0.0, 0.0, v, kn, ks, mu, dt, xi);
    ASSERT_TRUE(f.touching);
    if (std::fabs(f.ft) < mu * fn) {
      EXPECT_NEAR(f.ft, -ks * xi, 1e-12);  // elastic: spring force
      ++stuck_steps;
    } else {
      EXPECT_NEAR(f.ft, -mu * fn, 1e-12);  // slipping: on the limit
      EXPECT_NEAR(xi, mu * fn / ks, 1e-12);  // spring rescaled to sit on the limit
    }
  }
  // mu fn / ks = 0.006 of spring stretch at 1e-4 per step: 59 elastic steps, then slip.
  EXPECT_EQ(stuck_steps, 59);
  EXPECT_NEAR(f.fx, fn, 1e-9);  // normal force on j along n = +x
}

TEST(Coulomb, LoadJustBelowTheLimitSticksJustAboveSlips) {
  // A disc pressed by fn and pulled by a tangential load: the spring stretches to hold
  // 0.99 mu fn, and cannot hold 1.01 mu fn.
  const double kn = 1e4, ks = 5e3, mu = 0.3, overlap = 0.01, fn = kn * overlap;
  for (double ratio : {0.99, 1.01}) {
    const double load = ratio * mu * fn;
    // Quasi-static loading: xi grows until the spring balances the load or slips.
    double xi = 0;
    bool slipped = false;
    for (int s = 0; s < 10000; ++s) {
      const double stretch_rate = (load - ks * xi) > 0 ? 1e-5 : 0.0;
      const ContactLane f = pair_contact(0.0, 1.0 - overlap, -stretch_rate, 0.0, kn, ks, mu, 1.0, xi);
      if (std::fabs(f.ft) >= mu * fn) { slipped = true; break; }
      if (stretch_rate == 0.0) break;
    }
    EXPECT_EQ(slipped, ratio > 1.0) << "load ratio " << ratio;
  }
}

struct TwoDiscs {
  World w;
  TwoDiscs() {
    inside(w).law.kn = 1e4;
    inside(w).law.ks = 5e3;
    inside(w).law.mu = 0.5;
    inside(w).law.restitution = 0.5;
    w.add_disc(0.0, 0.0, 0.5);
    w.add_disc(0.0, 0.9999, 0.5);  // rests on the driven disc under gravity
    inside(w).discs.motion[0] = static_cast<std::uint8_t>(Motion::Kinematic);  // driven
    inside(w).dt = 0.5 * w.stable_dt();
  }
  double history() const { return w.neighbors().size() ? w.contacts().pairs.xi[0] : 0.0; }
  std::size_t driven() const { return w.discs().id[0] == 0 ? 0 : 1; }
  // Slides the driven disc along the tangent so that the spring stretches.
  void shear(int steps) {
    inside(w).discs.vx[driven()] = 0.01;
    for (int s = 0; s < steps; ++s) w.advance();
    inside(w).discs.vx[driven()] = 0.0;
  }
};

TEST(Coulomb, HistoryIsKeptAcrossListRebuilds) {
  TwoDiscs t;
  t.shear(50);
  const double before = t.history();
  ASSERT_NE(before, 0.0);
  const auto builds = t.w.neighbors().builds;
  // Rebuild with spatial re-ordering: the pair gets new indices, the spring its old stretch.
  t.w.rebuild_contacts(true);
  EXPECT_EQ(t.w.neighbors().builds, builds + 1);
  EXPECT_EQ(t.history(), before);
}

TEST(Coulomb, HistoryIsDroppedOnSeparation) {
  TwoDiscs t;
  t.shear(50);
  ASSERT_NE(t.history(), 0.0);
  // Pull the driven disc away, beyond contact but within the skin: the pair stays listed,
  // its history is gone.
  const auto k = t.driven();
  inside(t.w).discs.vy[k] = -0.2;
  for (int s = 0; s < 100; ++s) t.w.advance();
  inside(t.w).discs.vy[k] = 0.0;
  t.w.advance();
  ASSERT_EQ(t.w.neighbors().size(), 1u);
  EXPECT_EQ(t.history(), 0.0);
}

}  // namespace
}  // namespace orogen
