// A rigid 3-disc cluster standing on two of its discs on a rough inclined wall (gravity
// tilted, MODEL §4): it stays put below the friction angle and slides with the Coulomb
// acceleration g (sin phi - mu cos phi) above it.
#include <gtest/gtest.h>

#include <array>

#include "world_fixtures.hpp"

namespace orogen {
namespace {

struct SlideResult {
  double displacement = 0, velocity = 0;
};

SlideResult slide(double tan_phi, double mu_wall, double duration) {
  World w;
  w.law.kn = 1e4;
  w.law.ks = 5e3;
  w.law.mu = 0.5;
  w.walls = {testing::wall(-100, 0, 100, 0, WallFriction::Rough, mu_wall)};
  // Equal discs: two on the wall, one on top of them.
  const std::array<std::size_t, 3> idx = {w.add_disc(-0.5, 0.5, 0.5), w.add_disc(0.5, 0.5, 0.5),
                                          w.add_disc(0.0, 0.5 + std::sqrt(3.0) / 2.0, 0.5)};
  w.add_cluster(idx);
  w.dt = 0.5 * w.stable_dt();
  // Let it sit down under upright gravity first, then tilt gravity.
  w.body.drag = 2.0;
  for (int s = 0; s < 4000; ++s) w.advance();
  w.body.drag = 0;
  const double phi = std::atan(tan_phi);
  w.body.gx = std::sin(phi);
  w.body.gy = -std::cos(phi);
  const double x_start = w.clusters.x[0];
  const int steps = static_cast<int>(duration / w.dt);
  for (int s = 0; s < steps; ++s) w.advance();
  return {w.clusters.x[0] - x_start, w.clusters.vx[0]};
}

TEST(Incline, ClusterStaysBelowFrictionAngle) {
  const auto r = slide(0.3, 0.4, 20.0);
  EXPECT_LT(std::fabs(r.displacement), 1e-3);
  EXPECT_LT(std::fabs(r.velocity), 1e-4);
}

TEST(Incline, ClusterSlidesWithCoulombAccelerationAboveIt) {
  const double tan_phi = 0.5, mu = 0.4, t = 10.0;
  const auto r = slide(tan_phi, mu, t);
  const double phi = std::atan(tan_phi);
  const double a = std::sin(phi) - mu * std::cos(phi);
  EXPECT_NEAR(r.velocity, a * t, 0.03 * a * t);
  EXPECT_NEAR(r.displacement, 0.5 * a * t * t, 0.05 * 0.5 * a * t * t);
}

}  // namespace
}  // namespace orogen
