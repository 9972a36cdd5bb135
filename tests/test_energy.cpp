// Frictionless, undamped discs in a box conserve energy (MODEL §3, §4).
#include <gtest/gtest.h>

#include "util/random.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

TEST(Energy, FrictionlessUndampedGasInABoxConservesEnergy) {
  World w;
  inside(w).body.gy = 0;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0;
  inside(w).law.restitution = 1.0;
  const double side = 24;
  w.set_walls({testing::wall(0, 0, side, 0), testing::wall(side, 0, side, side), testing::wall(side, side, 0, side),
             testing::wall(0, side, 0, 0)});
  Random rng(7);
  for (int row = 0; row < 15; ++row)
    for (int col = 0; col < 15; ++col) {
      const auto i = w.add_disc(1.0 + col * 1.5, 1.0 + row * 1.5, 0.5 * rng.uniform(0.7, 1.0));
      inside(w).discs.vx[i] = rng.uniform(-1, 1);
      inside(w).discs.vy[i] = rng.uniform(-1, 1);
    }
  // A tenth of the stability limit: the energy error of symplectic Euler at the switch-on and
  // switch-off of each contact grows with dt. Over 1e5 steps and three seeds the drift was
  // below 2.2e-4 here; at a quarter of the limit it reached 1.8e-3 for one seed, at half 5e-3.
  inside(w).dt = 0.1 * w.stable_dt();
  auto energy = [&] { return w.kinetic_energy() + testing::spring_energy(w); };
  // Average over a window: symplectic Euler's energy oscillates within each collision.
  auto window_mean = [&](int steps) {
    double sum = 0;
    for (int s = 0; s < steps; ++s) { w.advance(); sum += energy(); }
    return sum / steps;
  };
  const double e0 = window_mean(2000);
  for (int s = 0; s < 96000; ++s) w.advance();
  const double e1 = window_mean(2000);
  EXPECT_GT(e0, 40.0);  // the gas really moves: 225 discs at speeds ~0.8
  EXPECT_LT(std::fabs(e1 - e0) / e0, 1e-3) << "e0 = " << e0 << ", e1 = " << e1;
}

}  // namespace
}  // namespace orogen
