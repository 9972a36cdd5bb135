// A step cut between ranks that each hold a copy of the world and talk only through buffers
// (parallel/emulated_ranks.hpp, docs/domain-decomposition.md): over many steps, list builds and
// sorts, for any number of ranks and any cut, every bit as the step of one process; and with
// any one exchange left out, not.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <iostream>

#include "parallel/emulated_ranks.hpp"
#include "parallel/pair_migration.hpp"
#include "ranks_world.hpp"

namespace orogen {
namespace {

using testing::lopsided_cut;
using testing::mixed_heap;
using testing::same_bits;
using testing::state_of;

// Three shares whose bounds move at every list build, far from where the pairs would cut them:
// at each build much of the state changes keeper.
ThreadSplit moving_cut(const NeighborList& L, const Discs& d, const Clusters& c, int ranks) {
  EXPECT_EQ(ranks, 3);
  const auto chunks = static_cast<std::ptrdiff_t>(L.chunk_start.size()) - 1;
  const auto n = static_cast<std::ptrdiff_t>(d.size()), nc = static_cast<std::ptrdiff_t>(c.size());
  const auto shift = static_cast<std::ptrdiff_t>(L.builds % 5);
  return {{0, chunks / 3 + shift, 2 * chunks / 3 - shift, chunks},
          {0, n / 3 + 13 * shift, 2 * n / 3 - 7 * shift, n},
          {0, nc / 3 + 3 * shift, 2 * nc / 3 - 5 * shift, nc}};
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

// More ranks than chunks: some ranks search no chunk of the list (nor step any pair), and the
// others' pairs still reach them.
TEST(EmulatedRanks, RanksWithoutAShareOfTheSearchStepAsOneProcess) {
  const World start = mixed_heap(3, 6, 2000);
  const std::size_t chunks = start.neighbors().chunk_start.size() - 1;
  ASSERT_LT(chunks, 20u);  // a few ranks more than chunks
  expect_same_run(start, static_cast<int>(chunks) + 2, {}, 300, 25);
}

// Rolling resistance (docs/model.md): a second history per pair, owned and gathered as the first.
TEST(EmulatedRanks, RollingResistanceStepsAsOneProcess) {
  World start = mixed_heap();
  ContactLaw law = start.law();
  law.rolling_friction = 0.3;
  start.set_contact_law(law);
  for (int ranks : {2, 3}) expect_same_run(start, ranks, lopsided_cut, 300, 25);
}

// A layered crust (named materials, bonds, a weakening base): a disc's slip travels as its
// motion and its sums do, a bond across a cut is stepped by both ranks, breaks reach every copy.
TEST(EmulatedRanks, LayeredCrustStepsAsOneProcess) {
  const World start = testing::layered_heap();
  const std::size_t bonds = start.bonds().size();
  ASSERT_GT(bonds, 100u);
  World one = start;
  for (int s = 0; s < 300; ++s) one.advance();
  const std::size_t broken = one.bonds().breaks.size();
  std::cout << bonds << " bonds, " << broken << " broken in 300 steps\n";
  EXPECT_GT(broken, 0u) << "no bond broke: the breaks' exchange is not tested";
  EXPECT_LT(broken, bonds / 2) << "most bonds broke: the bonds' forces are hardly tested";
  for (int ranks : {2, 3}) expect_same_run(start, ranks, {}, 300, 25);
  for (int ranks : {2, 3}) expect_same_run(start, ranks, lopsided_cut, 300, 25);
  expect_same_run(start, 3, moving_cut, 300, 25);  // slip migrates with the motion
}

TEST(EmulatedRanks, LopsidedCutsStepAsOneProcess) {
  const World start = mixed_heap();
  for (int ranks : {2, 3}) expect_same_run(start, ranks, lopsided_cut, 300, 25);
  expect_same_run(start, 3, moving_cut, 300, 25);  // a cut that moves at every build: the state migrates
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

// A list build over ranks reads every rank's positions alone; the rest of the state moves to its
// new keeper after it (parallel/migration.hpp). Left out, the copies keep stale motion and
// histories where the cut or the sort moved them, and the bits differ; and the builds' gathers
// carry much less than the whole state.
TEST(EmulatedRanks, MigrationAfterABuildMatters) {
  const World start = mixed_heap();
  World one = start;
  const std::uint64_t builds = one.neighbors().builds;
  int steps = 0;
  constexpr std::uint64_t kBuilds = 6;
  std::size_t listed = 0;  // pairs listed over the builds
  while (one.neighbors().builds < builds + kBuilds) {  // each build from the positions
    const std::uint64_t before = one.neighbors().builds;
    one.advance();
    if (one.neighbors().builds != before) listed += one.neighbors().size();
    ++steps;
  }
  const std::vector<double> expected = state_of(one);
  for (const bool drop : {false, true}) {
    EmulatedRanks many(start, 3, moving_cut);
    if (drop) many.drop_for_testing(Exchange::Migration);
    bool same = false;
    try {
      for (int s = 0; s < steps; ++s) many.advance();
      same = same_bits(state_of(many.gathered()), expected);
    } catch (const InstabilityError&) {
    }
    EXPECT_EQ(same, !drop) << (drop ? "migration left out, yet the same bits" : "not the bits of one process");
    // Each copy holds the pairs of its own chunks (and of those it searched); the others' are
    // placeholders, a disc with itself, until a whole copy gathers them.
    for (int r = 0; r < many.ranks() && !drop; ++r) {
      const NeighborList& L = many.rank(r).world().neighbors();
      std::size_t placeholders = 0;
      for (std::size_t p = 0; p < L.size(); ++p) placeholders += L.first[p] == L.second[p];
      EXPECT_GT(placeholders, L.size() / 5) << "rank " << r << " holds most of the list";
      const PairRange own = rank_pairs(L, many.rank(r).plan().cut, r);
      for (std::size_t p = own.begin; p < own.end; ++p) ASSERT_NE(L.first[p], L.second[p]) << "rank " << r;
    }
    std::uint64_t migrated = 0, gathered = 0, position_gathers = 0, list_values = 0, searched = 0;
    for (int r = 0; r < many.ranks(); ++r) {
      const auto& work = many.rank(r).serial_work();
      migrated += work.migrated_values;
      gathered += work.gathered_values;
      position_gathers += work.position_gathers;
      EXPECT_GT(work.searched_pairs, 0u) << "rank " << r << " searched no share of the list";
      searched += work.searched_pairs;
      list_values += work.list_values;
    }
    // Each rank searched its share of each build, every pair once; it sent a pair (one value)
    // only to the rank that keeps its chunk under the cut made after the search, which here,
    // moving at every build, takes some chunks from the rank that searched them.
    if (!drop) {
      EXPECT_EQ(searched, listed);
      EXPECT_GT(list_values, 0u);
      EXPECT_LT(list_values, listed / 4);
    }
    EXPECT_EQ(position_gathers, 3 * kBuilds) << "each rank gathers the positions for each build";
    std::cout << migrated << " values migrated\n";
    if (!drop) {
      EXPECT_GT(migrated, 0u) << "nothing migrated: the test does not test it";
    }
    // A whole-state gather sends every rank's share to the 2 others: at least 6 doubles a disc
    // and 11 a body (motion alone, histories not counted) at each build. The positions are 2.
    const std::size_t motion = kBuilds * 2 * (6 * start.discs().size() + 11 * start.clusters().size());
    EXPECT_LT(gathered, motion / 2) << "the builds' gathers should carry the positions, not the whole state";
    std::cout << gathered << " values gathered, the motion alone " << motion << "\n";
  }
}

TEST(EmulatedRanks, RefusesWhatItDoesNotRunYet) {
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
  std::uint64_t migrated = 0;
  for (int r = 0; r < ranks; ++r) migrated += many.rank(r).serial_work().migrated_values;
  std::cout << "  all buffers, builds' gathers and migrations included: " << 8 * all / static_cast<std::size_t>(steps)
            << " bytes a step on average over " << steps << " steps, of which migrations "
            << 8 * migrated / static_cast<std::size_t>(steps) << "\n";
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
