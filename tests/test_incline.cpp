// A rigid 3-disc cluster standing on two of its discs on a rough inclined wall (gravity
// tilted, MODEL §4): it stays put below the friction angle and slides with the Coulomb
// acceleration g (sin phi - mu cos phi) above it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

struct SlideResult {
  double displacement = 0, velocity = 0;
};

SlideResult slide(double tan_phi, double mu_wall, double duration) {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.5;
  inside(w).walls = {testing::wall(-100, 0, 100, 0, WallFriction::Rough, mu_wall)};
  // Equal discs: two on the wall, one on top of them.
  const std::array<std::size_t, 3> idx = {w.add_disc(-0.5, 0.5, 0.5), w.add_disc(0.5, 0.5, 0.5),
                                          w.add_disc(0.0, 0.5 + std::sqrt(3.0) / 2.0, 0.5)};
  w.add_cluster(idx);
  inside(w).dt = 0.5 * w.stable_dt();
  // Let it sit down under upright gravity first, then tilt gravity.
  inside(w).body.drag = 2.0;
  for (int s = 0; s < 4000; ++s) w.advance();
  inside(w).body.drag = 0;
  const double phi = std::atan(tan_phi);
  inside(w).body.gx = std::sin(phi);
  inside(w).body.gy = -std::cos(phi);
  const double x_start = w.clusters().x[0];
  const int steps = static_cast<int>(duration / w.dt());
  for (int s = 0; s < steps; ++s) w.advance();
  return {w.clusters().x[0] - x_start, w.clusters().vx[0]};
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

// Issue 39.2, a weakening base: the cluster on a floor whose mu 0.5 falls to 0.25 over 1 d of each
// disc's slip, gravity tilted to tan 0.4 (between the two), kicked down the slope at speed 1.
// Without weakening it decelerates at g (sin - 0.5 cos) and stops; with it, the friction falls
// as it slides, and once every disc has slipped 1 d it accelerates at g (sin - 0.25 cos).
struct WeakeningSlide {
  double stopped_after = -1;  // time the cluster stood still (-1: never)
  double late_acceleration = 0, slip = 0;
};

WeakeningSlide weakening_slide(double fraction) {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.5;
  inside(w).materials.list = {Material{.name = "rock", .friction = 0.5, .friction_residual = 0.5, .bond = {}}};
  Wall floor = testing::wall(-100, 0, 400, 0, WallFriction::Rough, 0.5);
  set_weakening(floor, BaseWeakening{fraction, 1.0});
  inside(w).walls = {floor};
  const std::array<std::size_t, 3> idx = {w.add_disc(-0.5, 0.5, 0.5), w.add_disc(0.5, 0.5, 0.5),
                                          w.add_disc(0.0, 0.5 + std::sqrt(3.0) / 2.0, 0.5)};
  w.add_cluster(idx);
  w.enable_materials();
  inside(w).dt = 0.5 * w.stable_dt();
  inside(w).body.drag = 2.0;
  for (int s = 0; s < 4000; ++s) w.advance();
  inside(w).body.drag = 0;
  const double phi = std::atan(0.4);
  inside(w).body.gx = std::sin(phi);
  inside(w).body.gy = -std::cos(phi);
  inside(w).clusters.vx[0] = 1.0;
  const double t0 = w.time();
  WeakeningSlide r;
  double v_at_20 = 0, t_at_20 = 0;
  const int steps = static_cast<int>(30.0 / w.dt());
  for (int s = 0; s < steps; ++s) {
    w.advance();
    if (r.stopped_after < 0 && std::fabs(w.clusters().vx[0]) < 1e-3) r.stopped_after = w.time() - t0;
    if (s == static_cast<int>(20.0 / w.dt())) { v_at_20 = w.clusters().vx[0]; t_at_20 = w.time(); }
  }
  r.late_acceleration = (w.clusters().vx[0] - v_at_20) / (w.time() - t_at_20);
  r.slip = std::min(w.discs().slip[0], w.discs().slip[1]);
  return r;
}

TEST(Incline, AWeakeningBaseLetsAKickedClusterRunAwayAtTheResidualAcceleration) {
  const double phi = std::atan(0.4);
  const WeakeningSlide firm = weakening_slide(0.0), weak = weakening_slide(0.5);
  const double stop_time = 1.0 / (0.5 * std::cos(phi) - std::sin(phi));  // v0 / deceleration
  EXPECT_GT(firm.stopped_after, 0) << "a firm base must stop the cluster";
  EXPECT_LT(firm.stopped_after, 1.2 * stop_time);
  EXPECT_DOUBLE_EQ(firm.slip, 0.0) << "a firm wall adds no slip to its discs";
  EXPECT_LT(weak.stopped_after, 0) << "a weakening base must not stop it";
  EXPECT_GT(weak.slip, 10.0);
  const double residual = std::sin(phi) - 0.25 * std::cos(phi);
  EXPECT_NEAR(weak.late_acceleration, residual, 0.03 * residual);
}

}  // namespace
}  // namespace orogen
