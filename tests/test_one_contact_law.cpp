// The contact law is written once (contact/law_kernels.hpp, contact/normal_laws.hpp); every
// user of it must get bitwise the same forces: the vectorised block kernels (with rolling
// resistance too) and one pair through the kernel, the pair and wall force stages of a step, and the contact output
// (analysis/contact_forces.cpp), for every registered normal law; the biaxial servo's elastic
// wall force is the normal force without the dashpot.
#include <gtest/gtest.h>

#include <cstring>

#include "analysis/biaxial_walls.hpp"
#include "analysis/contact_forces.hpp"
#include "contact/contact_block.hpp"
#include "contact/normal_laws.hpp"
#include "util/random.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(OneContactLaw, BlockKernelMatchesOnePairThroughTheKernel) {
  for (std::size_t law = 0; law < kNormalLawCount; ++law) {
    with_normal_law(law, [&](auto normal) {
      using Normal = decltype(normal);
      const double kn = 2e4, ks = 2e4 * 2 / 7, mu = 0.5, dt = 5e-4, kr_per_r2 = ks;
      Random rng(42);
      ContactBlock b;
      int touching = 0, slipping = 0;
      for (int round = 0; round < 200; ++round) {
        double xi[kContactBlock], roll[kContactBlock];
        for (int k = 0; k < kContactBlock; ++k) {
          b.ri[k] = rng.uniform(0.35, 0.5);
          b.rj[k] = rng.uniform(0.35, 0.5);
          const double dist = (b.ri[k] + b.rj[k]) * rng.uniform(0.97, 1.02);  // some apart
          const double angle = rng.uniform(0, 6.283185307179586);
          b.dx[k] = dist * std::cos(angle);
          b.dy[k] = dist * std::sin(angle);
          b.dvx[k] = rng.uniform(-1, 1);
          b.dvy[k] = rng.uniform(-1, 1);
          b.wi[k] = rng.uniform(-2, 2);
          b.wj[k] = rng.uniform(-2, 2);
          b.gn[k] = rng.uniform(0, 50);
          b.gs[k] = 0.5 * b.gn[k];
          b.xi[k] = xi[k] = rng.uniform(-0.01, 0.01);  // large ones slip at once
          b.mu[k] = mu;
          b.mur[k] = rng.uniform(0, 0.5);
          b.roll[k] = roll[k] = rng.uniform(-0.02, 0.02);
        }
        ContactBlock with_materials = b, with_rolling = b;
        contact_forces_block<Normal>(b, kContactBlock, kn, ks, mu, dt);
        contact_forces_block_materials<Normal>(with_materials, kContactBlock, kn, ks, dt);
        contact_forces_block_rolling<Normal>(with_rolling, kContactBlock, kn, ks, kr_per_r2, dt);
        for (int k = 0; k < kContactBlock; ++k) {
          const ContactLane f = contact_lane<Normal>(b.dx[k], b.dy[k], b.ri[k], b.rj[k], b.dvx[k], b.dvy[k], b.wi[k],
                                                     b.wj[k], b.gn[k], b.gs[k], xi[k], kn, ks, mu, dt);
          ASSERT_EQ(f.touching, b.touching[k] != 0);
          EXPECT_TRUE(same_bits(f.xi, b.xi[k])) << f.xi << " vs " << b.xi[k];
          EXPECT_TRUE(same_bits(f.fx, b.fx[k]));
          EXPECT_TRUE(same_bits(f.fy, b.fy[k]));
          EXPECT_TRUE(same_bits(f.ft, b.ft[k]));
          // The materials' block (each pair's own friction, here all mu) gives the same bits.
          EXPECT_TRUE(same_bits(f.xi, with_materials.xi[k]));
          EXPECT_TRUE(same_bits(f.fx, with_materials.fx[k]));
          EXPECT_TRUE(same_bits(f.ft, with_materials.ft[k]));
          EXPECT_TRUE(same_bits(f.slip, with_materials.slip[k]));
          // The rolling block: the same contact, and the rolling lane of the pair.
          const RollingLane r = rolling_lane(f.touching, b.ri[k], b.rj[k], b.wi[k], b.wj[k], roll[k],
                                             Normal::load(f.fn), kr_per_r2, with_rolling.mur[k], dt);
          EXPECT_TRUE(same_bits(f.fx, with_rolling.fx[k]));
          EXPECT_TRUE(same_bits(f.ft, with_rolling.ft[k]));
          EXPECT_TRUE(same_bits(r.moment, with_rolling.moment[k]));
          EXPECT_TRUE(same_bits(r.roll, with_rolling.roll[k]));
          if (!f.touching) continue;
          ++touching;
          slipping += f.at_limit;
        }
      }
      EXPECT_GT(touching, 2000) << Normal::name;  // the sample covers both cases ...
      EXPECT_GT(slipping, 100) << Normal::name;   // ... and contacts on the Coulomb limit
    });
  }
}

// Discs thrown into a box with a rough floor, a smooth left wall, a traction belt on the right
// and a rough backstop moving in: pairs and walls colliding, sticking and slipping.
World box(std::size_t normal_law) {
  World w;
  inside(w).law.normal_force = normal_law;
  inside(w).law.kn = 2e4;
  inside(w).law.ks = 2e4 * 2 / 7;
  inside(w).law.mu = 0.5;
  inside(w).law.tangential_damping_ratio = 0.3;
  if (normal_law != 0) {  // the restitution calibration is the linear no-pull law's
    inside(w).law.damping = NormalDamping::PerMass;
    inside(w).law.damping_rate = 150;
  }
  inside(w).neighbors.skin = 0.3;
  const double width = 40;
  Wall belt = testing::wall(width, 0, width, 30, WallFriction::Traction, 0.4);
  belt.traction_gamma = 5;
  belt.surface_speed = 0.5;
  Wall backstop = testing::wall(8, 0.5, 8, 30, WallFriction::Rough, 0.6);
  backstop.vx = 0.3;
  inside(w).walls = {testing::wall(0, 0, width, 0, WallFriction::Rough, 0.5), testing::wall(0, 0, 0, 30), belt, backstop};
  Random rng(7);
  for (int row = 0; row < 8; ++row)
    for (int col = 0; col < 30; ++col) {
      const auto i = w.add_disc(9.0 + col * 1.0, 0.6 + row * 1.05, 0.5 * rng.uniform(0.7, 1.0));
      inside(w).discs.vx[i] = rng.uniform(-1, 1);
      inside(w).discs.vy[i] = rng.uniform(-1, 0);
    }
  inside(w).dt = 0.5 * w.stable_dt();
  return w;
}

// The per-disc forces the force stages sum, rebuilt from the contact output's rows in the
// stages' order: pairs chunk by chunk, even chunks then odd ones, then walls in wall order.
std::vector<DiscForce> forces_from_output(const World& w, const ContactList& c) {
  const auto& L = w.neighbors();
  const auto& d = w.discs();
  std::vector<std::ptrdiff_t> row(L.size(), -1);
  std::size_t r = 0;
  for (std::size_t p = 0; p < L.size(); ++p)
    if (r < c.size() && !c.is_wall[r] && c.index_a[r] == L.first[p] && c.index_b[r] == L.second[p])
      row[p] = static_cast<std::ptrdiff_t>(r++);
  std::vector<DiscForce> f(d.size(), DiscForce{0.0, 0.0, 0.0});
  for (std::size_t parity = 0; parity < 2; ++parity)
    for (std::size_t k = parity; k + 1 < L.chunk_start.size(); k += 2)
      for (auto p = L.chunk_start[k]; p < L.chunk_start[k + 1]; ++p) {
        if (row[p] < 0) continue;
        const auto q = static_cast<std::size_t>(row[p]);
        const auto i = L.first[p], j = L.second[p];
        f[i].fx -= c.fx[q]; f[i].fy -= c.fy[q]; f[i].torque += -d.radius[i] * c.ft[q];
        f[j].fx += c.fx[q]; f[j].fy += c.fy[q]; f[j].torque += -d.radius[j] * c.ft[q];
      }
  for (; r < c.size(); ++r) {
    const auto i = static_cast<std::size_t>(c.index_b[r]);
    f[i].fx += c.fx[r]; f[i].fy += c.fy[r]; f[i].torque += -d.radius[i] * c.ft[r];
  }
  return f;
}

TEST(OneContactLaw, ForceStagesAndContactOutputGiveTheSameBits) {
  for (std::size_t law = 0; law < kNormalLawCount; ++law) {
    World w = box(law);
    std::size_t pairs = 0, walls = 0, wall_slips = 0, pair_slips = 0;
    bool pulled = false;
    for (int s = 1; s <= 3000; ++s) {
      w.advance();
      if (s % 150 != 0) continue;
      // A current list, so that the output and the next step's stages see the same contacts.
      w.rebuild_contacts(false);
      inside(w).moved = 0;
      const ContactList c = measure_contact_forces(w);
      World next = w;
      std::vector<DiscForce> forces;
      testing::record_step_forces(next, forces);
      next.step_stages();
      const auto expected = forces_from_output(w, c);
      ASSERT_EQ(expected.size(), forces.size());
      for (std::size_t i = 0; i < expected.size(); ++i) {
        ASSERT_TRUE(same_bits(expected[i].fx, forces[i].fx)) << "law " << law << " step " << s;
        ASSERT_TRUE(same_bits(expected[i].fy, forces[i].fy)) << "law " << law << " step " << s;
        ASSERT_TRUE(same_bits(expected[i].torque, forces[i].torque)) << "law " << law << " step " << s;
      }
      // The wall stage's flags are those of the output's rows.
      std::size_t r = 0;
      while (r < c.size() && !c.is_wall[r]) {
        pair_slips += c.at_limit[r];
        pulled = pulled || c.fn[r] < 0;
        ++r;
      }
      pairs += r;
      const auto& wc = next.contacts().walls;
      for (std::size_t k = 0; k < wc.size(); ++k) {
        if (!wc.touching[k]) continue;
        ASSERT_LT(r, c.size());
        EXPECT_EQ(static_cast<std::size_t>(c.index_b[r]), wc.disc[k]);
        EXPECT_EQ(c.at_limit[r], wc.at_limit[k]);
        wall_slips += wc.at_limit[k];
        ++r, ++walls;
      }
      EXPECT_EQ(r, c.size());
    }
    EXPECT_GT(pairs, 1000u) << law << ": " << pairs << " pairs, " << walls << " walls, " << pair_slips << " and " << wall_slips << " slipping";
    EXPECT_GT(walls, 200u) << law;
    EXPECT_GT(pair_slips, 20u) << law;
    EXPECT_GT(wall_slips, 20u) << law;
    if (law == normal_law_index("linear_pull")) {
      EXPECT_TRUE(pulled);
    }
  }
}

TEST(OneContactLaw, BiaxialElasticWallForceIsTheNormalForceWithoutDashpot) {
  World w = box(0);
  for (int s = 0; s < 2000; ++s) w.advance();
  w.rebuild_contacts(false);
  inside(w).moved = 0;
  // At rest and with walls at rest the dashpots give nothing: the output's normal force is
  // the elastic one.
  for (std::size_t i = 0; i < inside(w).discs.size(); ++i) inside(w).discs.vx[i] = inside(w).discs.vy[i] = inside(w).discs.omega[i] = 0;
  for (auto& wall : inside(w).walls) wall.vx = wall.vy = wall.surface_speed = 0;
  const ContactList c = measure_contact_forces(w);
  std::vector<WallForce> expected(w.walls().size());
  for (std::size_t r = 0; r < c.size(); ++r) {
    if (!c.is_wall[r]) continue;
    auto& e = expected[static_cast<std::size_t>(c.id_a[r])];  // every wall enabled: row = index
    e.fx -= c.fn[r] * c.nx[r];
    e.fy -= c.fn[r] * c.ny[r];
  }
  const auto got = elastic_wall_forces(w);
  double largest = 0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_NEAR(got[k].fx, expected[k].fx, 1e-9 * (1 + std::fabs(expected[k].fx))) << "wall " << k;
    EXPECT_NEAR(got[k].fy, expected[k].fy, 1e-9 * (1 + std::fabs(expected[k].fy))) << "wall " << k;
    largest = std::max(largest, std::hypot(got[k].fx, got[k].fy));
  }
  EXPECT_GT(largest, 10.0);  // the floor carries the pile
}

}  // namespace
}  // namespace orogen
