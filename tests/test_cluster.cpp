// Rigid clusters: a free spinning body conserves angular momentum and stays rigid.
#include <gtest/gtest.h>

#include <array>

#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

// Angular momentum about the centre of mass from the member discs' own states.
double disc_angular_momentum(const World& w, double cx, double cy) {
  double l = 0;
  for (std::size_t i = 0; i < w.discs().size(); ++i) {
    const double m = w.discs().mass[i];
    l += m * ((w.discs().x[i] - cx) * w.discs().vy[i] - (w.discs().y[i] - cy) * w.discs().vx[i]) +
         w.discs().omega[i] / w.discs().inv_inertia[i];
  }
  return l;
}

TEST(Cluster, FreeSpinningClusterConservesAngularMomentum) {
  World w;
  inside(w).body.gy = 0;
  const double r1 = 0.35, r2 = 0.5, r3 = 0.42;
  const double a = r1 + r2, b = r1 + r3, c = r2 + r3;
  const double cos1 = (a * a + b * b - c * c) / (2 * a * b);
  const std::array<std::size_t, 3> idx = {w.add_disc(0, 0, r1), w.add_disc(a, 0, r2),
                                          w.add_disc(b * cos1, b * std::sqrt(1 - cos1 * cos1), r3)};
  w.add_cluster(idx);
  inside(w).clusters.omega[0] = 3.0;
  inside(w).clusters.vx[0] = 0.2;
  inside(w).clusters.vy[0] = -0.1;
  update_cluster_discs(inside(w).clusters, inside(w).discs);
  inside(w).dt = w.stable_dt();
  const double l0 = disc_angular_momentum(w, w.clusters().x[0], w.clusters().y[0]);
  const double d01 = std::hypot(w.discs().x[1] - w.discs().x[0], w.discs().y[1] - w.discs().y[0]);
  for (int s = 0; s < 100000; ++s) w.advance();
  const double l1 = disc_angular_momentum(w, w.clusters().x[0], w.clusters().y[0]);
  EXPECT_NEAR(l1, l0, 1e-9 * std::fabs(l0));
  EXPECT_GT(std::fabs(w.clusters().theta[0]), 100.0);  // it really spun (many turns)
  // Members keep their distances (touching pairwise) and the centre moves uniformly.
  std::array<std::size_t, 3> by_id{};
  for (std::size_t i = 0; i < 3; ++i) by_id[static_cast<std::size_t>(w.discs().id[i])] = i;
  const double d01_after = std::hypot(w.discs().x[by_id[1]] - w.discs().x[by_id[0]], w.discs().y[by_id[1]] - w.discs().y[by_id[0]]);
  EXPECT_NEAR(d01_after, d01, 1e-9);
  EXPECT_NEAR(d01, r1 + r2, 1e-12);
  EXPECT_NEAR(w.clusters().vx[0], 0.2, 1e-15);
}

// A spinning cluster dropped onto a rough floor: its forces (and the lever arms of their
// torques) must be those of its discs where they were when the forces were computed, whether or
// not free discs share the world (free discs take an integration pass of their own).
std::array<double, 4> tumble(bool with_free_disc) {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.5;
  inside(w).walls = {testing::wall(-100, 0, 100, 0, WallFriction::Rough, 0.5)};
  const std::array<std::size_t, 3> idx = {w.add_disc(-0.5, 0.6, 0.5), w.add_disc(0.5, 0.6, 0.5),
                                          w.add_disc(0.0, 0.6 + std::sqrt(3.0) / 2.0, 0.5)};
  w.add_cluster(idx);
  inside(w).clusters.omega[0] = 2.0;
  inside(w).clusters.vx[0] = 0.3;
  update_cluster_discs(inside(w).clusters, inside(w).discs);
  if (with_free_disc) w.add_disc(50.0, 0.5, 0.5);  // far away, resting on the floor
  inside(w).dt = 0.5 * w.stable_dt();
  for (int s = 0; s < 4000; ++s) w.advance();
  return {w.clusters().x[0], w.clusters().y[0], w.clusters().theta[0], w.clusters().omega[0]};
}

TEST(Cluster, MotionDoesNotDependOnUnrelatedFreeDiscs) {
  const auto alone = tumble(false), mixed = tumble(true);
  EXPECT_GT(std::fabs(alone[2]), 0.1);  // it turned while bouncing on the floor
  for (std::size_t k = 0; k < alone.size(); ++k) EXPECT_EQ(alone[k], mixed[k]) << "component " << k;
}

TEST(Cluster, InertiaFollowsParallelAxisTheorem) {
  World w;
  const std::array<std::size_t, 3> idx = {w.add_disc(0, 0, 0.5), w.add_disc(1, 0, 0.5),
                                          w.add_disc(0.5, std::sqrt(3.0) / 2, 0.5)};
  w.add_cluster(idx);
  const double m = M_PI * 0.25;
  // Three equal discs at the corners of a unit triangle: distance to the centroid 1/sqrt(3).
  const double inertia = 3 * (0.5 * m * 0.25 + m / 3.0);
  EXPECT_NEAR(1.0 / w.clusters().inv_inertia[0], inertia, 1e-12);
  EXPECT_NEAR(w.clusters().mass[0], 3 * m, 1e-12);
}

}  // namespace
}  // namespace orogen
