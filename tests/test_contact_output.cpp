// Contact forces, Love-Weber stress and cluster poses of an output step (analysis/
// contact_output.hpp) against statics: a resting column's stress is its weight, a settled
// layer's forces balance and its summed stress is the moment of its weight; and taking them
// never changes the trajectory.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "analysis/contact_forces.hpp"
#include "analysis/contact_output.hpp"
#include "analysis/love_weber_stress.hpp"
#include "io/snapshot_writer.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

// A small box of 48 discs of three sizes dropped onto a floor, pairs with friction, rough
// floor; and a two-disc cluster on top if asked. Discs are never re-ordered (indices stay put).
World layer_world(bool with_cluster = true) {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.3;
  w.set_walls({testing::wall(0, 0, 10, 0, WallFriction::Rough, 0.3), testing::wall(0, 0, 0, 30),
             testing::wall(10, 0, 10, 30)});
  const double radii[] = {0.5, 0.4, 0.45};
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 8; ++i) w.add_disc(0.7 + 1.2 * i + 0.05 * (j % 2), 0.6 + 1.2 * j, radii[(i + j) % 3]);
  if (with_cluster) {
    const std::array<std::size_t, 2> body = {w.add_disc(4.5, 8.5, 0.5), w.add_disc(5.5, 8.5, 0.5)};
    w.add_cluster(body);
  }
  inside(w).sort_every = 0;
  inside(w).dt = 0.5 * w.stable_dt();
  return w;
}

void settle(World& w, int steps) {
  inside(w).body.drag = 2.0;  // settle quickly; drag vanishes at rest
  for (int s = 0; s < steps; ++s) w.advance();
}

// Sum over contacts of the force each disc feels, by disc index.
std::vector<std::array<double, 2>> contact_force_sums(const World& w, const ContactList& c) {
  std::vector<std::array<double, 2>> f(w.discs().size(), {0.0, 0.0});
  for (std::size_t k = 0; k < c.size(); ++k) {
    f[c.index_b[k]][0] += c.fx[k];
    f[c.index_b[k]][1] += c.fy[k];
    if (c.is_wall[k]) continue;
    f[c.index_a[k]][0] -= c.fx[k];
    f[c.index_a[k]][1] -= c.fy[k];
  }
  return f;
}

TEST(ContactOutput, TakingItLeavesTheTrajectoryBitwiseTheSame) {
  World with = layer_world(), without = layer_world();
  const ContactOutputOptions all{true, true, 2.0};
  std::size_t groups = 0;
  for (int s = 0; s < 6000; ++s) {
    if (s % 97 == 0) groups += contact_output_groups(with, all).size();
    with.advance();
    without.advance();
  }
  EXPECT_GT(groups, 0u);
  ASSERT_EQ(with.discs().size(), without.discs().size());
  for (std::size_t i = 0; i < with.discs().size(); ++i) {
    EXPECT_EQ(with.discs().x[i], without.discs().x[i]) << i;
    EXPECT_EQ(with.discs().y[i], without.discs().y[i]) << i;
    EXPECT_EQ(with.discs().vx[i], without.discs().vx[i]) << i;
    EXPECT_EQ(with.discs().omega[i], without.discs().omega[i]) << i;
  }
  EXPECT_EQ(with.contacts().pairs.xi, without.contacts().pairs.xi);
  EXPECT_EQ(with.contacts().walls.xi, without.contacts().walls.xi);
}

// Also with a list the next step must rebuild first (measured on a rebuilt copy).
TEST(ContactOutput, ForcesAreThoseTheNextStepApplies) {
  for (const bool stale_list : {false, true}) {
    World w = layer_world();
    for (int s = 0; s < 3000; ++s) w.advance();  // falling and colliding
    if (stale_list) w.invalidate_neighbors();
    const ContactList c = measure_contact_forces(w);
    ASSERT_GT(c.size(), 20u);
    const auto sums = contact_force_sums(w, c);
    std::vector<DiscForce> forces;
    testing::record_step_forces(w, forces);
    w.advance();
    ASSERT_EQ(forces.size(), w.discs().size());
    for (std::size_t i = 0; i < w.discs().size(); ++i) {
      const double scale = 1e-12 * (1 + std::fabs(forces[i].fx) + std::fabs(forces[i].fy));
      EXPECT_NEAR(sums[i][0], forces[i].fx, scale) << i << (stale_list ? " (stale list)" : "");
      EXPECT_NEAR(sums[i][1], forces[i].fy, scale) << i << (stale_list ? " (stale list)" : "");
    }
  }
}

TEST(ContactOutput, RestingColumnStressIsItsWeight) {
  const int n = 10;
  const double r = 0.5;
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0;
  inside(w).walls = {testing::wall(-5, 0, 5, 0)};
  for (int k = 0; k < n; ++k) w.add_disc(0.0, r + k * 2 * r, r);
  inside(w).dt = 0.5 * w.stable_dt();
  settle(w, 20000);
  const ContactList c = measure_contact_forces(w);
  const DiscStress s = love_weber_stress(w.discs(), c);
  const double m = std::numbers::pi * r * r, area = m;  // mass pi r^2
  for (std::size_t i = 0; i < w.discs().size(); ++i) {
    // The k-th disc from the top is pressed by k discs from above and held by k + 1 from below,
    // each load at about r from its centre: sigma_yy A = -(2k + 1) m g r (overlaps of ~1e-3 r aside).
    const double k = std::round((2 * r * n - w.discs().y[i] - r) / (2 * r));
    const double expected = -(2 * k + 1) * m * r / area;
    EXPECT_NEAR(s.yy[i], expected, 2e-3 * std::fabs(expected)) << "disc " << k << " from the top";
    EXPECT_NEAR(s.xx[i], 0.0, 1e-9);
    EXPECT_NEAR(s.xy[i], 0.0, 1e-9);
  }
  // The floor carries the whole column.
  double floor = 0;
  for (std::size_t k = 0; k < c.size(); ++k)
    if (c.is_wall[k]) floor += c.fy[k];
  EXPECT_NEAR(floor, n * m, 1e-6 * n * m);
}

// Free discs only: the rigid links inside a cluster carry forces that are no contacts.
TEST(ContactOutput, SettledLayerBalancesAndItsStressIsTheMomentOfItsWeight) {
  World w = layer_world(false);
  settle(w, 40000);
  const ContactList c = measure_contact_forces(w);
  const DiscStress s = love_weber_stress(w.discs(), c);
  const auto& d = w.discs();
  double weight = 0, mg_y = 0, mg_x = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    weight += d.mass[i];
    mg_y += d.mass[i] * w.body().gy * d.y[i];
    mg_x += d.mass[i] * w.body().gy * d.x[i];
  }
  // Every disc: contact forces + weight = 0.
  const auto sums = contact_force_sums(w, c);
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_NEAR(sums[i][0], 0.0, 1e-4 * d.mass[i]) << i;
    EXPECT_NEAR(sums[i][1], d.mass[i], 1e-4 * d.mass[i]) << i;
  }
  // The walls carry the weight (the smooth side walls push only sideways, and cancel).
  double wall_fy = 0, wall_fx = 0, wall_moment_yy = 0, wall_moment_yx = 0, wall_moment_xx = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (!c.is_wall[k]) continue;
    wall_fx += c.fx[k];
    wall_fy += c.fy[k];
    wall_moment_yy += c.fy[k] * c.y[k];
    wall_moment_yx += c.fy[k] * c.x[k];
    wall_moment_xx += c.fx[k] * c.x[k];
  }
  EXPECT_NEAR(wall_fy, weight, 1e-5 * weight);
  EXPECT_NEAR(wall_fx, 0.0, 1e-5 * weight);
  // sum_i sigma_i A_i = sum_c f (x) (x_c - x_i) over every disc's contacts; pair forces cancel
  // at their shared point, and each disc's contact forces sum to -m_i g at rest, so it equals
  // sum over wall contacts of f (x) x_c + sum_i m_i g (x) x_i.
  double syy = 0, syx = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    syy += s.yy[i] * s.area[i];
    syx += s.yx[i] * s.area[i];
    sxx += s.xx[i] * s.area[i];
    sxy += s.xy[i] * s.area[i];
  }
  const double scale = weight * 5.0;  // the moment arm of the layer's weight is a few d
  EXPECT_NEAR(syy, wall_moment_yy + mg_y, 1e-4 * scale);
  EXPECT_NEAR(syx, wall_moment_yx + mg_x, 1e-4 * scale);
  EXPECT_NEAR(sxx, wall_moment_xx, 1e-4 * scale);
  EXPECT_NEAR(sxy, syx, 1e-4 * scale);  // no net torque: the summed stress is symmetric
  EXPECT_LT(syy, -0.5 * weight);        // compression, about the weight times the centre's height
  // The grid keeps the sums: its cells times their area add up to the discs' sigma A.
  const StressGrid g = coarse_grain_stress(d, s, 2.0);
  double grid_yy = 0;
  for (double v : g.yy) grid_yy += v * g.cell * g.cell;
  EXPECT_NEAR(grid_yy, syy, 1e-9 * std::fabs(syy));
  EXPECT_GE(g.nx, 5u);
}

TEST(ContactOutput, GroupsCarryUnitsAndClusterPoses) {
  World w = layer_world();
  for (int s = 0; s < 3000; ++s) w.advance();
  SnapshotFrame frame;
  frame.discs = &w.discs();
  frame.groups = contact_output_groups(w, {true, true, 1.5});
  ASSERT_EQ(frame.groups.size(), 4u);
  EXPECT_EQ(frame.groups[0].name, "contacts");
  EXPECT_EQ(frame.groups[3].name, "clusters");
  const auto path = std::filesystem::temp_directory_path() / "orogen_test_contact_output.h5";
  write_single_snapshot(path, {}, frame);
  {
    h5::File f = h5::File::open(path, h5::File::Mode::ReadOnly);
    h5::Group out = h5::Group::open(f.id(), snapshot_group_name(0));
    EXPECT_TRUE(h5::is_group(out.id(), "contacts"));
    EXPECT_FALSE(h5::is_group(out.id(), "x"));
    h5::Group contacts = h5::Group::open(out.id(), "contacts");
    const auto fn = h5::read<double>(contacts.id(), "fn");
    EXPECT_EQ(fn.size(), measure_contact_forces(w).size());
    const hid_t id = H5Dopen2(contacts.id(), "fn", H5P_DEFAULT);
    ASSERT_GE(id, 0);
    h5::Object ds(id, H5Dclose);
    EXPECT_EQ(h5::get_attr_string(ds.id(), "units"), "m g");
    EXPECT_FALSE(h5::get_attr_string(ds.id(), "description").empty());
    h5::Group clusters = h5::Group::open(out.id(), "clusters");
    EXPECT_EQ(h5::read<double>(clusters.id(), "theta"), w.clusters().theta);
    const h5::Matrix seg = h5::read_2d(contacts.id(), "segment_points");
    EXPECT_EQ(seg.rows, 2 * fn.size());
    EXPECT_EQ(seg.cols, 2u);
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace orogen
