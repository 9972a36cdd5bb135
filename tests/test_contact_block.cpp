// The vectorised block kernel gives bitwise the same forces and histories as the readable
// scalar kernel, on random pairs covering touching, parted, sticking and slipping contacts.
#include <gtest/gtest.h>

#include <cstring>

#include "contact/contact_block.hpp"
#include "contact/contact_law.hpp"
#include "util/random.hpp"

namespace orogen {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(ContactBlock, MatchesTheScalarKernelBitForBit) {
  const double kn = 2e4, ks = 2e4 * 2 / 7, mu = 0.5, dt = 5e-4;
  Random rng(42);
  ContactBlock b;
  int touching = 0, slipping = 0;
  for (int round = 0; round < 200; ++round) {
    double xi[kContactBlock];
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
    }
    contact_forces_block(b, kContactBlock, kn, ks, mu, dt);
    for (int k = 0; k < kContactBlock; ++k) {
      PairForce f;
      const bool t = contact_force(b.dx[k], b.dy[k], b.ri[k], b.rj[k], b.dvx[k], b.dvy[k], b.wi[k], b.wj[k], kn,
                                   ks, mu, b.gn[k], b.gs[k], dt, xi[k], f);
      ASSERT_EQ(t, b.touching[k] != 0);
      EXPECT_TRUE(same_bits(xi[k], b.xi[k])) << xi[k] << " vs " << b.xi[k];
      if (!t) continue;
      ++touching;
      slipping += std::fabs(f.ft) >= mu * std::hypot(f.fx, f.fy) / std::sqrt(1 + mu * mu) * 0.999;
      EXPECT_TRUE(same_bits(f.fx, b.fx[k]));
      EXPECT_TRUE(same_bits(f.fy, b.fy[k]));
      EXPECT_TRUE(same_bits(f.ft, b.ft[k]));
    }
  }
  EXPECT_GT(touching, 2000);  // the sample covers both cases ...
  EXPECT_GT(slipping, 100);   // ... and contacts on the Coulomb limit
}

}  // namespace
}  // namespace orogen
