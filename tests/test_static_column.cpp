// A column of n discs resting on a wall: the bottom overlap carries the whole weight.
#include <gtest/gtest.h>

#include <string>

#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

TEST(StaticColumn, BottomOverlapEqualsWeightOverStiffness) {
  for (int n : {1, 5, 20}) {
    World w;
    inside(w).law.kn = 1e4;
    inside(w).law.ks = 5e3;
    inside(w).law.mu = 0;
    inside(w).walls = {testing::wall(-5, 0, 5, 0)};
    for (int k = 0; k < n; ++k) w.add_disc(0.0, 0.5 + k * 1.0, 0.5);
    inside(w).dt = 0.5 * w.stable_dt();
    inside(w).body.drag = 2.0;  // settle quickly; drag vanishes at rest
    for (int s = 0; s < 20000; ++s) w.advance();
    double bottom_y = 1e9;
    for (std::size_t i = 0; i < w.discs().size(); ++i) bottom_y = std::min(bottom_y, w.discs().y[i]);
    const double overlap = 0.5 - bottom_y;
    const double m = M_PI * 0.25;
    const double expected = n * m * 1.0 / w.law().kn;
    EXPECT_NEAR(overlap, expected, 0.02 * expected) << "n = " << n;
    // Each contact in the column carries the weight above it.
    std::vector<double> ys(w.discs().y.begin(), w.discs().y.end());
    std::sort(ys.begin(), ys.end());
    for (int k = 0; k + 1 < n; ++k) {
      const double contact_overlap = 1.0 - (ys[k + 1] - ys[k]);
      const double load = (n - k - 1) * m / w.law().kn;
      EXPECT_NEAR(contact_overlap, load, 0.02 * load) << "n = " << n << ", contact " << k;
    }
  }
}

// A disc squeezed slowly between two kinematic discs until they overlap by half a radius: the
// run stops, and names a load the contact cannot hold (not a collision or a fast boundary).
TEST(StaticColumn, SlowSqueezeStopsTheRunNamingTheLoad) {
  World w;
  inside(w).law.kn = 100;
  inside(w).law.ks = 50;
  inside(w).body.gx = 0;
  inside(w).body.gy = 0;
  const auto fixed = w.add_disc(0.0, 0.0, 0.5);
  w.add_disc(1.0, 0.0, 0.5);
  const auto pusher = w.add_disc(2.0, 0.0, 0.5);
  inside(w).discs.motion[fixed] = inside(w).discs.motion[pusher] = static_cast<std::uint8_t>(Motion::Kinematic);
  inside(w).discs.vx[pusher] = -0.01;
  inside(w).dt = 0.5 * w.stable_dt();
  std::string message;
  try {
    for (int s = 0; s < 100000; ++s) w.advance();
  } catch (const InstabilityError& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "the squeeze never stopped the run";
  EXPECT_NE(message.find("overlap by 5"), std::string::npos) << message;
  EXPECT_NE(message.find("a load too large for k_n = 100"), std::string::npos) << message;
  EXPECT_EQ(message.find("weight of"), std::string::npos) << message;  // no gravity here
}

}  // namespace
}  // namespace orogen
