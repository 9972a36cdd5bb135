// A step cut between ranks that each hold a copy of the world and talk only through buffers
// (parallel/emulated_ranks.hpp, docs/domain-decomposition.md): over many steps, list builds and
// sorts, for any number of ranks and any cut, every bit as the step of one process; and with
// any one exchange left out, not.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <iostream>

#include "parallel/emulated_ranks.hpp"
#include "util/random.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen {
namespace {

// A settling heap of free discs and three-disc clusters in a rough box, long in x so that the
// list has many chunks (as tests/test_thread_split.cpp's), with a kinematic body and a
// kinematic disc, the right wall pushing in, and a sort at every second list build.
World mixed_heap(int rows = 6, int cols = 50, int settle_steps = 5000) {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.5;
  const double width = 2.15 * cols + 3.2, height = 2.4 * rows + 2;
  w.set_walls({testing::wall(0, 0, width, 0, WallFriction::Rough, 0.5),
               testing::wall(0, 0, 0, height, WallFriction::Rough, 0.5),
               testing::wall(width, 0, width, height, WallFriction::Rough, 0.5)});
  Random rng(3);
  for (int row = 0; row < rows; ++row)
    for (int col = 0; col < cols; ++col) {
      // Rows shifted by half a column, so that the rows settle into each other's gaps.
      const double x = 1.6 + col * 2.15 + (row % 2) * 1.05 + rng.uniform(-0.04, 0.04), y = 0.6 + row * 2.0;
      if ((row + col) % 3 == 0) {  // a cluster: three touching discs of radius 0.5
        const std::array<std::size_t, 3> idx = {w.add_disc(x - 0.5, y, 0.5), w.add_disc(x + 0.5, y, 0.5),
                                                w.add_disc(x, y + 0.866025403784, 0.5)};
        const double vx = rng.uniform(-0.5, 0.5);
        for (const auto i : idx) inside(w).discs.vx[i] = vx;
        w.add_cluster(idx);
      } else {
        const auto i = w.add_disc(x, y + 0.4, 0.5 * rng.uniform(0.7, 1.0));
        inside(w).discs.vx[i] = rng.uniform(-0.5, 0.5);
      }
    }
  update_cluster_discs(inside(w).clusters, inside(w).discs);
  inside(w).dt = 0.5 * w.stable_dt();
  w.set_sort_every(2);
  w.edit_motion([&](MotionEdit& e) {
    e.cluster(1, Motion::Kinematic, 0.02, 0);
    for (std::size_t i = 0; i < w.discs().size(); ++i)
      if (w.discs().cluster[i] < 0) { e.disc(i, Motion::Kinematic, -0.02, 0); break; }
  });
  for (int s = 0; s < settle_steps; ++s) w.advance();
  inside(w).walls[2].vx = -0.05;  // the right wall pushes in: its contacts change, the list follows
  return w;
}

// Everything a step changes, in one array of doubles: equal arrays are equal bits.
std::vector<double> state_of(const World& w) {
  std::vector<double> s;
  const Discs& d = w.discs();
  for (const auto* a : {&d.x, &d.y, &d.vx, &d.vy, &d.omega, &d.theta}) s.insert(s.end(), a->begin(), a->end());
  for (const auto id : d.id) s.push_back(static_cast<double>(id));  // the order of a sort
  const Clusters& c = w.clusters();
  for (const auto* a : {&c.x, &c.y, &c.theta, &c.vx, &c.vy, &c.omega, &c.rot_c, &c.rot_s})
    s.insert(s.end(), a->begin(), a->end());
  s.insert(s.end(), w.contacts().pairs.xi.begin(), w.contacts().pairs.xi.end());
  s.insert(s.end(), w.contacts().walls.xi.begin(), w.contacts().walls.xi.end());
  for (const auto t : w.contacts().walls.touching) s.push_back(t);
  for (const auto& wall : w.walls()) s.insert(s.end(), {wall.ax, wall.ay, wall.bx, wall.by});
  s.insert(s.end(), {w.moved(), w.time(), static_cast<double>(w.step()), static_cast<double>(w.neighbors().builds)});
  return s;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Cuts far from split_threads': one rank with almost all the chunks, discs cut far from the
// chunks and bodies far from the discs, so that every exchange has something to carry.
ThreadSplit lopsided_cut(const NeighborList& L, const Discs& d, const Clusters& c, int ranks) {
  const auto chunks = static_cast<std::ptrdiff_t>(L.chunk_start.size()) - 1;
  const auto n = static_cast<std::ptrdiff_t>(d.size()), nc = static_cast<std::ptrdiff_t>(c.size());
  if (ranks == 2) return {{0, 1, chunks}, {0, n - 5, n}, {0, 1, nc}};
  return {{0, chunks / 3, chunks - 1, chunks}, {0, 7, n / 2, n}, {0, nc - 2, nc - 1, nc}};
}

// Steps a copy of `start` one process's way and over `ranks` emulated ranks, comparing every
// `every` steps.
void expect_same_run(const World& start, int ranks, RankCut cut, int steps, int every) {
  World one = start;
  EmulatedRanks many(start, ranks, std::move(cut));
  const std::uint64_t builds = one.neighbors().builds;
  for (int s = 1; s <= steps; ++s) {
    one.advance();
    many.advance();
    if (s % every == 0) {
      ASSERT_TRUE(same_bits(state_of(many.gathered()), state_of(one))) << ranks << " ranks, step " << s;
    }
  }
  EXPECT_GE(one.neighbors().builds - builds, 4u) << "the run should rebuild (and sort) its list several times";
}

TEST(EmulatedRanks, AnyNumberOfRanksStepsAsOneProcess) {
  const World start = mixed_heap();
  ASSERT_GT(start.neighbors().chunk_start.size(), 9u);
  for (int ranks : {1, 2, 3, 4}) expect_same_run(start, ranks, {}, 300, 25);
}

TEST(EmulatedRanks, LopsidedCutsStepAsOneProcess) {
  const World start = mixed_heap();
  for (int ranks : {2, 3}) expect_same_run(start, ranks, lopsided_cut, 300, 25);
}

// Every exchange matters: left out, it leaves a stale value in some copy and the bits differ.
TEST(EmulatedRanks, EachExchangeLeftOutChangesTheResult) {
  const World start = mixed_heap();
  World one = start;
  for (int s = 0; s < 3; ++s) one.advance();
  const std::vector<double> expected = state_of(one);
  for (const Exchange e : {Exchange::Ghosts, Exchange::PartialSums, Exchange::PairSums, Exchange::WholeSums}) {
    EmulatedRanks many(start, 3, lopsided_cut);
    many.drop_for_testing(e);
    bool differs = false;
    try {
      for (int s = 0; s < 3; ++s) many.advance();
      differs = !same_bits(state_of(many.gathered()), expected);
    } catch (const InstabilityError&) {
      differs = true;
    }
    const ExchangePlan& plan = many.rank(0).plan();
    const Routes& routes = e == Exchange::Ghosts        ? plan.ghosts
                           : e == Exchange::PartialSums ? plan.partial_sums
                           : e == Exchange::PairSums    ? plan.pair_sums
                                                        : plan.whole_sums;
    EXPECT_GT(routes.total(), 0u) << "exchange " << static_cast<int>(e) << " carries nothing in this test";
    EXPECT_TRUE(differs) << "exchange " << static_cast<int>(e) << " left out, yet the same bits";
  }
  // And with none left out, the same bits (the check above is not a check of something else).
  EmulatedRanks many(start, 3, lopsided_cut);
  for (int s = 0; s < 3; ++s) many.advance();
  EXPECT_TRUE(same_bits(state_of(many.gathered()), expected));
}

TEST(EmulatedRanks, RefusesWhatItDoesNotRunYet) {
  World with_materials = mixed_heap(2, 10, 10);
  with_materials.enable_materials();
  EXPECT_THROW(EmulatedRanks(with_materials, 2), std::invalid_argument);
  World with_hook = mixed_heap(2, 10, 10);
  with_hook.hooks().add(Stage::AfterIntegration, "test.hook", [](World&) {});
  EXPECT_THROW(EmulatedRanks(with_hook, 2), std::invalid_argument);
}

// What the ranks send each other per step (printed; docs/domain-decomposition.md): discs per
// exchange, per pair of neighbouring ranks, for the plan of the last list build.
void print_volume(const World& start, int ranks, int steps) {
  EmulatedRanks many(start, ranks);
  for (int s = 0; s < steps; ++s) many.advance();
  const ExchangePlan& plan = many.rank(0).plan();
  std::cout << start.discs().size() << " discs, " << plan.cut.chunk.back() << " chunks, " << ranks << " ranks, "
            << many.gathered().neighbors().builds - start.neighbors().builds << " list builds in " << steps
            << " steps:\n";
  for (int r = 0; r < ranks; ++r)
    for (int q = 0; q < ranks; ++q) {
      if (q == r) continue;
      const std::size_t ghosts = plan.ghosts(r, q).size(), partial = plan.partial_sums(r, q).size(),
                        pair = plan.pair_sums(r, q).size(), whole = plan.whole_sums(r, q).size();
      if (ghosts + partial + pair + whole == 0) continue;
      std::cout << "  " << r << " -> " << q << ": ghosts " << ghosts << ", partial sums " << partial
                << ", pair sums " << pair << ", whole sums " << whole << " (discs; "
                << 8 * (5 * ghosts + 3 * (partial + pair + whole)) << " bytes a step)\n";
    }
  std::size_t all = 0;
  for (int r = 0; r < ranks; ++r)
    for (int q = 0; q < ranks; ++q) all += many.mailbox().values_sent(r, q);
  std::cout << "  all buffers, builds' gathers included: " << 8 * all / static_cast<std::size_t>(steps)
            << " bytes a step on average over " << steps << " steps\n";
}

TEST(EmulatedRanks, ExchangeVolume) {
  const World start = mixed_heap();
  for (int ranks : {2, 4}) print_volume(start, ranks, 100);
}

// The same for a layer of some 19,000 discs, 1500 d long and about 10 d thick (seconds to settle):
//   orogen_tests --gtest_filter='*ExchangeVolumeOfALongLayer' --gtest_also_run_disabled_tests
TEST(EmulatedRanks, DISABLED_ExchangeVolumeOfALongLayer) {
  const World start = mixed_heap(16, 700, 5000);
  for (int ranks : {2, 4, 8}) print_volume(start, ranks, 200);
}

}  // namespace
}  // namespace orogen
