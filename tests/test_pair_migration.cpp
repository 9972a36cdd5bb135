// The pairs' histories across a list build over ranks (src/parallel/pair_migration.hpp): each
// rank sends the pairs it kept to the rank whose chunks list them after the build, found from
// the new stripes alone, and the receiver writes them into its own chunks. The step over ranks
// is bit for bit one process's only if this reaches every pair that changed keeper
// (tests/test_emulated_ranks.cpp checks the whole); here the rule itself, on a heap whose list
// is cut one way before a build and another way after it.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "contact/cell_grid.hpp"
#include "contact/disc_scan.hpp"
#include "contact/pair_search.hpp"
#include "contact/store_carry.hpp"
#include "parallel/pair_migration.hpp"
#include "ranks_world.hpp"

namespace orogen {
namespace {

TEST(PairMigration, LeavingPairsReachTheRankThatListsThem) {
  World w = testing::mixed_heap();
  for (int s = 0; s < 40; ++s) w.advance();  // the discs moved since the last build
  constexpr int kRanks = 3;
  const ThreadSplit before = split_threads(w.neighbors(), w.discs(), w.clusters(), kRanks);
  const PairContacts& old_pairs = w.contacts().pairs;
  std::map<std::pair<std::int64_t, std::int64_t>, std::pair<double, int>> old_history;  // by ids: xi, keeper
  for (int r = 0; r < kRanks; ++r) {
    const PairRange kept = rank_pairs(w.neighbors(), before, r);
    for (std::size_t p = kept.begin; p < kept.end; ++p)
      if (old_pairs.xi[p] != 0.0) old_history[{old_pairs.id_first[p], old_pairs.id_second[p]}] = {old_pairs.xi[p], r};
  }
  ASSERT_GT(old_history.size(), 100u);

  // Every rank's kept pairs, packed for the cut after the build (the list of the present positions).
  RankAccess access(w);
  std::vector<KeptPairs> kept(kRanks);
  for (int r = 0; r < kRanks; ++r)
    kept[static_cast<std::size_t>(r)] = record_kept_pairs(access, rank_pairs(w.neighbors(), before, r));
  const Discs& d = w.discs();
  NeighborList list;
  list.skin = w.neighbors().skin;
  const CellBins bins = bin_discs(d, make_grid(d, 2.0 * scan_discs(d).r_max + list.skin));
  search_pairs(list, bins, d);
  const ThreadSplit after = testing::lopsided_cut(list, d, w.clusters(), kRanks);
  std::vector<std::vector<std::vector<double>>> sent(kRanks);  // by sender, then receiver
  for (int r = 0; r < kRanks; ++r)
    sent[static_cast<std::size_t>(r)] = pack_leaving_pairs(kept[static_cast<std::size_t>(r)], bins.grid, after, r);

  // Each rank writes what it received into its chunks: every pair of them with a history kept
  // by another rank gets that history; its own stay 0 here (its own carry gives them).
  PairContacts pairs;
  set_pair_ids(pairs, list, d);
  pairs.xi.assign(list.size(), 0.0);
  std::size_t moved = 0;
  for (int q = 0; q < kRanks; ++q) {
    std::vector<std::vector<double>> received(kRanks);
    for (int r = 0; r < kRanks; ++r)
      if (r != q)
        received[static_cast<std::size_t>(r)] = sent[static_cast<std::size_t>(r)][static_cast<std::size_t>(q)];
    EXPECT_TRUE(sent[static_cast<std::size_t>(q)][static_cast<std::size_t>(q)].empty());  // its own pairs stay
    const PairRange own = rank_pairs(list, after, q);
    unpack_arriving_pairs(pairs, own, received, false);
    for (std::size_t p = own.begin; p < own.end; ++p) {
      const auto it = old_history.find({pairs.id_first[p], pairs.id_second[p]});
      const bool from_another = it != old_history.end() && it->second.second != q;
      EXPECT_EQ(pairs.xi[p], from_another ? it->second.first : 0.0) << "pair " << p << " on rank " << q;
      moved += from_another;
    }
  }
  EXPECT_GT(moved, 10u);  // the lopsided cut after the build moves many pairs to another keeper
}

}  // namespace
}  // namespace orogen
