// The pair search chunk by chunk: chunks searched apart and joined make the list of one whole
// search, a chunk's pairs lie in its own stripes and the one after, and the ranks the stripes
// give each disc cover those the list gives. A list built over ranks (each rank searching its
// own chunks, docs/domain-decomposition.md) rests on all three.
#include <gtest/gtest.h>

#include <algorithm>

#include "contact/cell_grid.hpp"
#include "contact/disc_scan.hpp"
#include "contact/pair_search.hpp"
#include "parallel/exchange_plan.hpp"
#include "parallel/stripe_ranks.hpp"
#include "ranks_world.hpp"

namespace orogen {
namespace {

TEST(PairSearch, ChunksSearchedApartJoinToTheWholeSearch) {
  World w = testing::mixed_heap();
  const Discs& d = w.discs();
  const double skin = w.neighbors().skin;
  const CellBins bins = bin_discs(d, make_grid(d, 2.0 * scan_discs(d).r_max + skin));
  const PairChunks chunks = pair_chunks(bins.grid);
  ASSERT_GE(chunks.count, 6);

  NeighborList whole;
  whole.skin = skin;
  const PairSearchResult one = search_pairs(whole, bins, d);
  ASSERT_GT(whole.size(), d.size() / 2);  // a heap, not a gas

  // Three uneven shares, as three ranks would search them.
  const std::int64_t cuts[] = {0, 1, chunks.count / 2 + 1, chunks.count};
  std::vector<ChunkPairs> found;
  for (int r = 0; r < 3; ++r) {
    auto share = search_pair_chunks(bins, d, skin, cuts[r], cuts[r + 1]);
    EXPECT_EQ(share.size(), static_cast<std::size_t>(cuts[r + 1] - cuts[r]));
    for (auto& c : share) found.push_back(std::move(c));
  }
  NeighborList joined;
  const PairSearchResult apart = join_pair_chunks(joined, found, chunks.stripes_per_chunk);
  EXPECT_EQ(joined.first, whole.first);
  EXPECT_EQ(joined.second, whole.second);
  EXPECT_EQ(joined.chunk_start, whole.chunk_start);
  EXPECT_EQ(apart.touching, one.touching);
  EXPECT_EQ(apart.stripes_per_chunk, one.stripes_per_chunk);
  EXPECT_EQ(apart.stats.max_overlap_ratio, one.stats.max_overlap_ratio);
  EXPECT_EQ(apart.stats.worst_a, one.stats.worst_a);
  EXPECT_EQ(apart.stats.worst_b, one.stats.worst_b);

  // Chunk k's pairs have their lower stripe in chunk k and reach at most one stripe past it.
  const CellGrid& g = bins.grid;
  auto stripe = [&](std::uint32_t i) { return g.cell_of(d.x[i], d.y[i]) / g.nv(); };
  for (std::int64_t k = 0; k < chunks.count; ++k) {
    const std::int64_t lo = k * chunks.stripes_per_chunk;
    const std::int64_t hi = std::min(g.nu(), lo + chunks.stripes_per_chunk);  // one past the chunk
    for (auto p = whole.chunk_start[static_cast<std::size_t>(k)]; p < whole.chunk_start[static_cast<std::size_t>(k) + 1]; ++p) {
      const std::int64_t sa = stripe(whole.first[p]), sb = stripe(whole.second[p]);
      EXPECT_GE(std::min(sa, sb), lo);
      EXPECT_LT(std::min(sa, sb), hi);
      EXPECT_LE(std::max(sa, sb), hi);
    }
  }
}

// The ranks that the stripes say can name a disc include every rank the list's pairs name it in,
// cut evenly by pair counts and lopsidedly: a plan from the stripes covers the plan from the list.
TEST(StripeRanks, CoverTheRanksThatTheListGives) {
  World w = testing::mixed_heap();
  const Discs& d = w.discs();
  const double skin = w.neighbors().skin;
  const CellBins bins = bin_discs(d, make_grid(d, 2.0 * scan_discs(d).r_max + skin));
  NeighborList list;
  list.skin = skin;
  search_pairs(list, bins, d);
  for (const ThreadSplit& cut : {split_threads(list, d, w.clusters(), 3), testing::lopsided_cut(list, d, w.clusters(), 3)}) {
    const ExchangePlan plan = make_exchange_plan(list, w.contacts().walls, d, w.clusters(), cut, Bonds{}, 0);
    const StripeRanks stripes = stripe_chunk_ranks(bins.grid, d, cut);
    std::size_t named = 0, more = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      for (const auto& [from_list, from_stripes] : {std::pair{plan.even_rank[i], stripes.even[i]},
                                                    std::pair{plan.odd_rank[i], stripes.odd[i]}}) {
        if (from_list != kNoRank) {
          EXPECT_EQ(from_stripes, from_list) << "disc " << i;
          ++named;
        } else {
          more += from_stripes != kNoRank;
        }
      }
    }
    EXPECT_GT(named, d.size() / 2);
    EXPECT_LT(more, named);  // a superset, not every rank for every disc
  }
}

// The ranks' shares of the search: whole chunks, each once, in order, with about as many discs
// each (at most one chunk's discs more than an even share); more shares than chunks leave some
// empty.
TEST(PairSearch, RangesByDiscsCoverEveryChunkOnceAndShareTheDiscs) {
  World w = testing::mixed_heap();
  const Discs& d = w.discs();
  const CellBins bins = bin_discs(d, make_grid(d, 2.0 * scan_discs(d).r_max + w.neighbors().skin));
  const PairChunks chunks = pair_chunks(bins.grid);
  const CellGrid& g = bins.grid;
  auto discs_before = [&](std::int64_t k) {
    return static_cast<double>(bins.cell_start[static_cast<std::size_t>(std::min(g.nu(), k * chunks.stripes_per_chunk) * g.nv())]);
  };
  double largest_chunk = 0;
  for (std::int64_t k = 0; k < chunks.count; ++k) largest_chunk = std::max(largest_chunk, discs_before(k + 1) - discs_before(k));
  for (const int shares : {1, 2, 3, 5, static_cast<int>(chunks.count), static_cast<int>(chunks.count) + 7}) {
    const auto bounds = chunk_ranges_by_discs(bins, shares);
    ASSERT_EQ(bounds.size(), static_cast<std::size_t>(shares) + 1);
    EXPECT_EQ(bounds.front(), 0);
    EXPECT_EQ(bounds.back(), chunks.count);
    EXPECT_TRUE(std::is_sorted(bounds.begin(), bounds.end()));
    for (int r = 0; r < shares; ++r) {
      const double share = discs_before(bounds[static_cast<std::size_t>(r) + 1]) - discs_before(bounds[static_cast<std::size_t>(r)]);
      EXPECT_LE(share, static_cast<double>(d.size()) / shares + largest_chunk) << shares << " shares, share " << r;
    }
  }
}

TEST(PairSearch, AnEmptyRangeFindsNothing) {
  World w = testing::mixed_heap(2, 10, 10);
  const Discs& d = w.discs();
  const CellBins bins = bin_discs(d, make_grid(d, 2.0 * scan_discs(d).r_max + w.neighbors().skin));
  EXPECT_TRUE(search_pair_chunks(bins, d, w.neighbors().skin, 3, 3).empty());
}

}  // namespace
}  // namespace orogen
