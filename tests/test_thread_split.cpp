// How a step's work is cut between threads (ThreadSplit): the shares cover every chunk, disc and
// body once, follow the chunks, and no split, however lopsided, changes a single bit.
#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "contact/thread_split.hpp"
#include "util/random.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

// A settling heap of free discs and three-disc clusters in a rough box, long in x so that the
// list has many chunks, with its neighbour list built (and the discs sorted) by a few steps.
World mixed_heap() {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.5;
  const double width = 120, height = 12;
  w.set_walls({testing::wall(0, 0, width, 0, WallFriction::Rough, 0.5),
             testing::wall(0, 0, 0, height, WallFriction::Rough, 0.5),
             testing::wall(width, 0, width, height, WallFriction::Rough, 0.5)});
  Random rng(3);
  for (int row = 0; row < 5; ++row)
    for (int col = 0; col < 38; ++col) {
      const double x = 1.6 + col * 3.1, y = 0.6 + row * 2.1;
      if ((row + col) % 3 == 0) {
        testing::add_triangle_cluster(w, x, y);
      } else {
        const auto i = w.add_disc(x, y + 0.4, 0.5 * rng.uniform(0.7, 1.0));
        inside(w).discs.vx[i] = rng.uniform(-0.5, 0.5);
      }
    }
  update_cluster_discs(inside(w).clusters, inside(w).discs);
  inside(w).dt = 0.5 * w.stable_dt();
  inside(w).sort_every = 1;  // every build sorts, so the list always carries its chunks' first discs
  for (int s = 0; s < 400; ++s) w.advance();
  return w;
}

// One step's forces and update with the given split; the step's force sums and the disc state
// after it.
std::vector<double> step_with(World w, const ThreadSplit& split) {
  std::vector<DiscForce> forces;
  testing::record_step_forces(w, forces);
  w.step_stages(&split);
  std::vector<double> state;
  for (const auto* a : {&w.discs().x, &w.discs().y, &w.discs().vx, &w.discs().vy, &w.discs().omega, &w.discs().theta})
    state.insert(state.end(), a->begin(), a->end());
  for (const auto& f : forces) state.insert(state.end(), {f.fx, f.fy, f.torque});
  state.insert(state.end(), w.contacts().pairs.xi.begin(), w.contacts().pairs.xi.end());
  state.insert(state.end(), w.contacts().walls.xi.begin(), w.contacts().walls.xi.end());
  return state;
}

TEST(ThreadSplit, SharesCoverEverythingOnceAndFollowTheChunks) {
  const World w = mixed_heap();
  const auto& L = w.neighbors();
  const auto chunks = static_cast<std::ptrdiff_t>(L.chunk_start.size()) - 1;
  ASSERT_GT(chunks, 8);
  ASSERT_EQ(L.chunk_disc.size(), L.chunk_start.size());  // the first build sorted the discs
  std::size_t largest_chunk = 0;
  for (std::ptrdiff_t k = 0; k < chunks; ++k)
    largest_chunk = std::max<std::size_t>(largest_chunk, L.chunk_start[k + 1] - L.chunk_start[k]);
  for (int threads : {1, 2, 3, 4}) {
    const ThreadSplit s = split_threads(L, w.discs(), w.clusters(), threads);
    ASSERT_EQ(s.threads(), threads);
    EXPECT_EQ(s.chunk.front(), 0);
    EXPECT_EQ(s.chunk.back(), chunks);
    EXPECT_EQ(s.disc.front(), 0);
    EXPECT_EQ(s.disc.back(), static_cast<std::ptrdiff_t>(w.discs().size()));
    EXPECT_EQ(s.body.front(), 0);
    EXPECT_EQ(s.body.back(), static_cast<std::ptrdiff_t>(w.clusters().size()));
    for (int t = 0; t < threads; ++t) {
      EXPECT_LE(s.chunk[t], s.chunk[t + 1]);
      EXPECT_LE(s.disc[t], s.disc[t + 1]);
      EXPECT_LE(s.body[t], s.body[t + 1]);
      // Equal shares of the pairs, to within one chunk.
      const double share = static_cast<double>(L.chunk_start[s.chunk[t + 1]] - L.chunk_start[s.chunk[t]]);
      EXPECT_NEAR(share, static_cast<double>(L.size()) / threads, static_cast<double>(largest_chunk)) << threads;
      // The discs are cut where the chunks are.
      EXPECT_EQ(s.disc[t], static_cast<std::ptrdiff_t>(L.chunk_disc[s.chunk[t]]));
    }
  }
}

TEST(ThreadSplit, NoSplitChangesTheResult) {
  const World w = mixed_heap();
  const auto chunks = static_cast<std::ptrdiff_t>(w.neighbors().chunk_start.size()) - 1;
  const auto n = static_cast<std::ptrdiff_t>(w.discs().size());
  const auto nc = static_cast<std::ptrdiff_t>(w.clusters().size());
  const std::vector<double> one = step_with(w, split_threads(w.neighbors(), w.discs(), w.clusters(), 1));
  const std::vector<ThreadSplit> others = {
      split_threads(w.neighbors(), w.discs(), w.clusters(), 2),
      split_threads(w.neighbors(), w.discs(), w.clusters(), 3),
      {{0, 1, chunks}, {0, n - 5, n}, {0, 1, nc}},        // lopsided, and discs cut far from chunks
      {{0, chunks - 1, chunks}, {0, 7, n}, {0, nc - 2, nc}},
  };
  for (std::size_t k = 0; k < others.size(); ++k) {
    const std::vector<double> other = step_with(w, others[k]);
    ASSERT_EQ(other.size(), one.size());
    EXPECT_EQ(std::memcmp(other.data(), one.data(), one.size() * sizeof(double)), 0) << "split " << k;
  }
}

// Integration zeroes every disc's force sums once used (the next step's force stages add onto
// them without clearing): members of dynamic and kinematic bodies, free dynamic and kinematic
// discs, whichever thread integrates them.
TEST(ThreadSplit, ForceSumsAreZeroAfterEveryStep) {
  World w = mixed_heap();
  w.edit_motion([&](MotionEdit& e) {
    e.cluster(0, Motion::Kinematic, 0.01, 0);
    for (std::size_t i = 0; i < w.discs().size(); ++i)
      if (w.discs().cluster[i] < 0) { e.disc(i, Motion::Kinematic, -0.01, 0); break; }
  });
  const auto n = static_cast<std::ptrdiff_t>(w.discs().size());
  const auto nc = static_cast<std::ptrdiff_t>(w.clusters().size());
  w.advance();  // a list for the new motion
  const auto chunks = static_cast<std::ptrdiff_t>(w.neighbors().chunk_start.size()) - 1;
  std::vector<DiscForce> forces;
  testing::record_step_forces(w, forces);
  for (const ThreadSplit& split : {split_threads(w.neighbors(), w.discs(), w.clusters(), 1),
                                   split_threads(w.neighbors(), w.discs(), w.clusters(), 2),
                                   ThreadSplit{{0, 1, chunks}, {0, n - 5, n}, {0, 1, nc}}}) {
    w.step_stages(&split);
    std::size_t pushed = 0;
    for (const auto& f : forces) pushed += f.fx != 0 || f.fy != 0;
    EXPECT_GT(pushed, 0u);  // the sums were there during the step (the heap is still falling)
    for (std::size_t i = 0; i < w.discs().size(); ++i) {
      const DiscForce& f = w.scratch().forces[i];
      ASSERT_TRUE(f.fx == 0 && f.fy == 0 && f.torque == 0) << "disc " << i << " of " << n;
    }
  }
}

}  // namespace
}  // namespace orogen
