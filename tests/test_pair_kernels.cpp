// The force loop's two ways through a chunk's pairs (every pair through the kernel untested, or
// each tested and only the touching ones through it) give bitwise the same forces and
// histories wherever the chunk is split between them, and the list build lists each chunk's
// touching pairs first and counts them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "contact/neighbor_list.hpp"
#include "util/random.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

// A heap of polydisperse discs falling into a box, long in x so that the list has many chunks.
World falling_heap(double skin) {
  World w;
  inside(w).law.kn = 2e4;
  inside(w).law.ks = 2e4 * 2 / 7;
  inside(w).law.mu = 0.5;
  inside(w).neighbors.skin = skin;
  const double width = 80;
  w.set_walls({testing::wall(0, 0, width, 0, WallFriction::Rough, 0.5), testing::wall(0, 0, 0, 30),
             testing::wall(width, 0, width, 30)});
  Random rng(11);
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 78; ++col) {
      const auto i = w.add_disc(1.0 + col * 1.0, 0.6 + row * 1.05, 0.5 * rng.uniform(0.7, 1.0));
      inside(w).discs.vx[i] = rng.uniform(-0.3, 0.3);
    }
  inside(w).dt = 0.5 * w.stable_dt();
  return w;
}

enum class Split { AsBuilt, AllTested, NoneTested };

// The disc forces, pair histories and disc states after one step's forces and update, with
// each chunk split between untested and tested pairs as the build left it, or all one way.
std::vector<double> forces_with(World w, Split split) {
  auto& L = inside(w).neighbors;
  for (std::size_t k = 0; k < L.chunk_touching.size(); ++k) {
    if (split == Split::AllTested) L.chunk_touching[k] = 0;
    if (split == Split::NoneTested) L.chunk_touching[k] = L.chunk_start[k + 1] - L.chunk_start[k];
  }
  w.step_stages();
  std::vector<double> out;
  for (const auto& f : w.scratch().forces) out.insert(out.end(), {f.fx, f.fy, f.torque});
  out.insert(out.end(), w.contacts().pairs.xi.begin(), w.contacts().pairs.xi.end());
  for (const auto* a : {&w.discs().x, &w.discs().y, &w.discs().vx, &w.discs().vy, &w.discs().omega})
    out.insert(out.end(), a->begin(), a->end());
  return out;
}

std::size_t touching_pairs(const World& w) {
  std::size_t n = 0;
  const auto& d = w.discs();
  for (std::size_t p = 0; p < w.neighbors().size(); ++p) {
    const auto i = w.neighbors().first[p], j = w.neighbors().second[p];
    n += std::hypot(d.x[j] - d.x[i], d.y[j] - d.y[i]) < d.radius[i] + d.radius[j];
  }
  return n;
}

TEST(PairKernels, TestedAndUntestedPairsGiveTheSameBits) {
  World w = falling_heap(0.3);
  std::size_t compared = 0, touching = 0, apart = 0;
  for (int s = 1; s <= 3000; ++s) {
    w.advance();
    if (s % 250 != 0) continue;
    const auto built = forces_with(w, Split::AsBuilt);
    for (const Split other : {Split::AllTested, Split::NoneTested}) {
      const auto v = forces_with(w, other);
      ASSERT_EQ(built.size(), v.size());
      ASSERT_EQ(0, std::memcmp(built.data(), v.data(), v.size() * sizeof(double))) << "step " << s;
    }
    compared += built.size();
    const std::size_t t = touching_pairs(w);
    touching += t;
    apart += w.neighbors().size() - t;
  }
  // Falling, colliding and at rest; many pairs of each kind.
  EXPECT_GT(compared, 30000u);
  EXPECT_GT(touching, 2000u);
  EXPECT_GT(apart, 2000u);
}

TEST(PairKernels, AChunkListsItsTouchingPairsFirst) {
  // A settled heap with a thin skin (most listed pairs touch) and a thick one (most do not).
  std::size_t touching_seen = 0, apart_seen = 0;
  for (const double skin : {0.05, 0.6}) {
    World w = falling_heap(skin);
    for (int s = 0; s < 4000; ++s) w.advance();
    w.rebuild_contacts(false);
    const auto& L = w.neighbors();
    ASSERT_EQ(L.chunk_touching.size() + 1, L.chunk_start.size());
    for (std::size_t k = 0; k + 1 < L.chunk_start.size(); ++k) {
      ASSERT_LE(L.chunk_touching[k], L.chunk_start[k + 1] - L.chunk_start[k]);
      for (auto p = L.chunk_start[k]; p < L.chunk_start[k + 1]; ++p) {
        const auto i = L.first[p], j = L.second[p];
        const double dx = w.discs().x[j] - w.discs().x[i], dy = w.discs().y[j] - w.discs().y[i];
        const double rsum = w.discs().radius[i] + w.discs().radius[j];
        const bool touching = dx * dx + dy * dy < rsum * rsum;
        EXPECT_EQ(touching, p < L.chunk_start[k] + L.chunk_touching[k]) << "chunk " << k << ", pair " << p;
        (touching ? touching_seen : apart_seen) += 1;
      }
    }
  }
  EXPECT_GT(touching_seen, 500u);
  EXPECT_GT(apart_seen, 500u);
}

}  // namespace
}  // namespace orogen
