// The force loop's two ways through a chunk (every pair through the kernel for a dense chunk,
// only the touching ones for a loose chunk) give bitwise the same forces and histories, and the
// list build calls a chunk dense when most of its pairs touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "contact/neighbor_list.hpp"
#include "util/random.hpp"
#include "world_fixtures.hpp"

namespace orogen {
namespace {

// A heap of polydisperse discs falling into a box, long in x so that the list has many chunks.
World falling_heap(double skin) {
  World w;
  w.law.kn = 2e4;
  w.law.ks = 2e4 * 2 / 7;
  w.law.mu = 0.5;
  w.neighbors.skin = skin;
  const double width = 80;
  w.walls = {testing::wall(0, 0, width, 0, WallFriction::Rough, 0.5), testing::wall(0, 0, 0, 30),
             testing::wall(width, 0, width, 30)};
  Random rng(11);
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 78; ++col) {
      const auto i = w.add_disc(1.0 + col * 1.0, 0.6 + row * 1.05, 0.5 * rng.uniform(0.7, 1.0));
      w.discs.vx[i] = rng.uniform(-0.3, 0.3);
    }
  w.dt = 0.5 * w.stable_dt();
  return w;
}

// The disc forces, pair histories and disc states after one step's forces and update, with
// every chunk taken the given way.
std::vector<double> forces_with(World w, bool dense) {
  std::fill(w.neighbors.chunk_dense.begin(), w.neighbors.chunk_dense.end(), dense);
  w.step_stages();
  std::vector<double> out;
  for (const auto& f : w.scratch.forces) out.insert(out.end(), {f.fx, f.fy, f.torque});
  out.insert(out.end(), w.contacts.pairs.xi.begin(), w.contacts.pairs.xi.end());
  for (const auto* a : {&w.discs.x, &w.discs.y, &w.discs.vx, &w.discs.vy, &w.discs.omega})
    out.insert(out.end(), a->begin(), a->end());
  return out;
}

std::size_t touching_pairs(const World& w) {
  std::size_t n = 0;
  const auto& d = w.discs;
  for (std::size_t p = 0; p < w.neighbors.size(); ++p) {
    const auto i = w.neighbors.first[p], j = w.neighbors.second[p];
    n += std::hypot(d.x[j] - d.x[i], d.y[j] - d.y[i]) < d.radius[i] + d.radius[j];
  }
  return n;
}

TEST(PairKernels, DenseAndLooseChunksGiveTheSameBits) {
  World w = falling_heap(0.3);
  std::size_t compared = 0, touching = 0, apart = 0;
  for (int s = 1; s <= 3000; ++s) {
    w.advance();
    if (s % 250 != 0) continue;
    const auto dense = forces_with(w, true), loose = forces_with(w, false);
    ASSERT_EQ(dense.size(), loose.size());
    ASSERT_EQ(0, std::memcmp(dense.data(), loose.data(), dense.size() * sizeof(double))) << "step " << s;
    compared += dense.size();
    const std::size_t t = touching_pairs(w);
    touching += t;
    apart += w.neighbors.size() - t;
  }
  // Falling, colliding and at rest; many pairs of each kind.
  EXPECT_GT(compared, 30000u);
  EXPECT_GT(touching, 2000u);
  EXPECT_GT(apart, 2000u);
}

TEST(PairKernels, AChunkIsDenseWhenMostOfItsPairsTouch) {
  // The settled heap with a thin skin (most listed pairs touch) and a thick one (most do not).
  std::size_t dense = 0, loose = 0;
  for (const double skin : {0.05, 0.6}) {
    World w = falling_heap(skin);
    for (int s = 0; s < 4000; ++s) w.advance();
    w.rebuild_contacts(false);
    const auto& L = w.neighbors;
    ASSERT_EQ(L.chunk_dense.size() + 1, L.chunk_start.size());
    for (std::size_t k = 0; k + 1 < L.chunk_start.size(); ++k) {
      std::size_t touching = 0;
      for (auto p = L.chunk_start[k]; p < L.chunk_start[k + 1]; ++p) {
        const auto i = L.first[p], j = L.second[p];
        touching += std::hypot(w.discs.x[j] - w.discs.x[i], w.discs.y[j] - w.discs.y[i]) <
                    w.discs.radius[i] + w.discs.radius[j];
      }
      const double share = static_cast<double>(touching) / (L.chunk_start[k + 1] - L.chunk_start[k]);
      EXPECT_EQ(L.chunk_dense[k] != 0, share >= 0.65) << "chunk " << k << ", skin " << skin << ": " << share;
      (L.chunk_dense[k] ? dense : loose) += 1;
    }
  }
  EXPECT_GT(dense, 10u);
  EXPECT_GT(loose, 10u);
}

}  // namespace
}  // namespace orogen
