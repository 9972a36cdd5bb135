#include "parallel/exchange_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace orogen {

ChunkRanks list_chunk_ranks(const NeighborList& L, const ThreadSplit& cut, std::size_t discs) {
  const std::size_t chunks = L.chunk_start.empty() ? 0 : L.chunk_start.size() - 1;
  const std::vector<std::int32_t> chunk_rank = rank_of_ranges(cut.chunk, chunks);
  std::vector<std::int64_t> chunk_of[2] = {std::vector<std::int64_t>(discs, -1), std::vector<std::int64_t>(discs, -1)};
  for (std::size_t k = 0; k < chunks; ++k) {
    auto& seen = chunk_of[k & 1];
    for (std::size_t p = L.chunk_start[k]; p < L.chunk_start[k + 1]; ++p)
      for (const std::uint32_t i : {L.first[p], L.second[p]}) {
        if (seen[i] >= 0 && seen[i] != static_cast<std::int64_t>(k))
          throw std::logic_error(fmt::format("disc {} lies in chunks {} and {} of one parity", i, seen[i], k));
        seen[i] = static_cast<std::int64_t>(k);
      }
  }
  ChunkRanks out{std::vector<std::int32_t>(discs, kNoRank), std::vector<std::int32_t>(discs, kNoRank)};
  for (std::size_t i = 0; i < discs; ++i) {
    if (chunk_of[0][i] >= 0) out.even[i] = chunk_rank[static_cast<std::size_t>(chunk_of[0][i])];
    if (chunk_of[1][i] >= 0) out.odd[i] = chunk_rank[static_cast<std::size_t>(chunk_of[1][i])];
  }
  return out;
}

std::vector<std::int32_t> rank_of_ranges(const std::vector<std::ptrdiff_t>& bounds, std::size_t items) {
  std::vector<std::int32_t> rank(items, kNoRank);
  for (std::size_t r = 0; r + 1 < bounds.size(); ++r)
    for (std::ptrdiff_t i = bounds[r]; i < bounds[r + 1]; ++i) rank[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(r);
  return rank;
}

std::size_t Routes::total() const {
  std::size_t n = 0;
  for (const auto& l : lists_) n += l.size();
  return n;
}

ExchangePlan make_exchange_plan(const NeighborList& L, const WallContacts& walls, const Discs& d, const Clusters& c,
                                const ThreadSplit& cut, const Bonds& bonds, std::size_t acting_bonds) {
  return make_exchange_plan(list_chunk_ranks(L, cut, d.size()), L.builds, walls, d, c, cut, bonds, acting_bonds);
}

ExchangePlan make_exchange_plan(ChunkRanks chunk_ranks, std::uint64_t build, const WallContacts& walls,
                                const Discs& d, const Clusters& c, const ThreadSplit& cut,
                                const Bonds& bonds, std::size_t acting_bonds) {
  const int ranks = cut.threads();
  const std::size_t n = d.size();
  ExchangePlan plan;
  plan.ranks = ranks;
  plan.cut = cut;
  plan.build = build;
  plan.even_rank = std::move(chunk_ranks.even);
  plan.odd_rank = std::move(chunk_ranks.odd);
  plan.wall_rank = rank_of_ranges(cut.disc, n);
  const std::vector<std::int32_t> body_rank = rank_of_ranges(cut.body, c.size());
  plan.step_rank.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    plan.step_rank[i] = d.cluster[i] >= 0 ? body_rank[static_cast<std::size_t>(d.cluster[i])] : plan.wall_rank[i];
  plan.touches_wall.assign(n, 0);
  for (const std::uint32_t i : walls.disc) plan.touches_wall[i] = 1;

  // A bond across a cut is stepped by both integrating ranks: each reads the other's disc.
  std::vector<std::pair<std::uint32_t, std::int32_t>> bond_readers;  // (disc, rank), sorted below
  for (std::size_t k = 0; k < acting_bonds; ++k) {
    const std::uint32_t a = bonds.a[k], b = bonds.b[k];
    if (plan.step_rank[a] == plan.step_rank[b]) continue;
    bond_readers.emplace_back(a, plan.step_rank[b]);
    bond_readers.emplace_back(b, plan.step_rank[a]);
  }
  std::sort(bond_readers.begin(), bond_readers.end());
  auto next_bond_reader = bond_readers.begin();

  plan.ghosts = plan.partial_sums = plan.pair_sums = plan.whole_sums = Routes(ranks);
  std::vector<std::int32_t> readers;
  for (std::size_t i = 0; i < n; ++i) {
    const auto disc = static_cast<std::uint32_t>(i);
    const std::int32_t even = plan.even_rank[i], odd = plan.odd_rank[i], wall = plan.wall_rank[i],
                       step = plan.step_rank[i];
    // The ranks that read the disc's motion in their force phases and bond steps; each needs it
    // from the rank that moved it last (once, if it reads it twice).
    readers.assign({even, odd, plan.touches_wall[i] ? wall : kNoRank});
    for (; next_bond_reader != bond_readers.end() && next_bond_reader->first == disc; ++next_bond_reader)
      readers.push_back(next_bond_reader->second);
    for (std::size_t k = 0; k < readers.size(); ++k) {
      const std::int32_t q = readers[k];
      const bool again = std::find(readers.begin(), readers.begin() + static_cast<std::ptrdiff_t>(k), q) !=
                         readers.begin() + static_cast<std::ptrdiff_t>(k);
      if (q != kNoRank && q != step && !again) plan.ghosts.add(step, q, disc);
    }
    // The running sum: even chunk, odd chunk, walls, integration. A rank with nothing to add
    // is skipped (a disc on no wall goes from its last chunk to its integrator).
    if (even != kNoRank && odd != kNoRank && even != odd) plan.partial_sums.add(even, odd, disc);
    std::int32_t holder = odd != kNoRank ? odd : even;
    if (plan.touches_wall[i]) {
      if (holder != kNoRank && holder != wall) plan.pair_sums.add(holder, wall, disc);
      holder = wall;
    }
    if (holder != kNoRank && holder != step) plan.whole_sums.add(holder, step, disc);
  }
  return plan;
}

}  // namespace orogen
