#include "parallel/pair_migration.hpp"

#include <algorithm>
#include <stdexcept>

#include "contact/pair_search.hpp"
#include "parallel/exchange_plan.hpp"
#include "parallel/packed_pair.hpp"

namespace orogen {
namespace {

std::uint64_t pair_key(std::int64_t first, std::int64_t second) {
  if (first < 0 || second < 0 || static_cast<std::uint64_t>(first) >= kPackedPairLimit ||
      static_cast<std::uint64_t>(second) >= kPackedPairLimit)
    throw std::logic_error("a disc id too large to send a pair's ids as one double");
  return static_cast<std::uint64_t>(first) << 32 | static_cast<std::uint64_t>(second);
}

}  // namespace

PairRange rank_pairs(const NeighborList& L, const ThreadSplit& cut, int rank) {
  if (L.chunk_start.empty()) return {0, 0};
  const auto r = static_cast<std::size_t>(rank);
  const auto chunk_start = [&](std::ptrdiff_t k) { return std::size_t{L.chunk_start[static_cast<std::size_t>(k)]}; };
  return {chunk_start(cut.chunk[r]), chunk_start(cut.chunk[r + 1])};
}

KeptPairs record_kept_pairs(const RankAccess& a, PairRange kept) {
  const PairContacts& pairs = a.contacts.pairs;
  const NeighborList& L = a.neighbors;
  const Discs& d = a.discs;
  const bool rolling = !pairs.roll.empty();
  KeptPairs out;
  for (std::size_t p = kept.begin; p < kept.end_in(pairs.size()); ++p) {
    const double roll = rolling ? pairs.roll[p] : 0.0;
    if (pairs.xi[p] == 0.0 && roll == 0.0) continue;  // no history: the receiver's carry gives 0 as well
    out.first.push_back(pairs.id_first[p]);
    out.second.push_back(pairs.id_second[p]);
    out.xi.push_back(pairs.xi[p]);
    if (rolling) out.roll.push_back(roll);
    out.x_first.push_back(d.x[L.first[p]]);
    out.y_first.push_back(d.y[L.first[p]]);
    out.x_second.push_back(d.x[L.second[p]]);
    out.y_second.push_back(d.y[L.second[p]]);
  }
  return out;
}

std::size_t leaving_pair_values(bool rolling) { return rolling ? 3 : 2; }

std::vector<std::vector<double>> pack_leaving_pairs(const KeptPairs& kept, const CellGrid& grid, const ThreadSplit& cut,
                                                    int rank) {
  const auto ranks = static_cast<std::size_t>(cut.threads());
  std::vector<std::vector<double>> out(ranks);
  const PairChunks chunks = pair_chunks(grid);
  const std::vector<std::int32_t> chunk_rank = rank_of_ranges(cut.chunk, static_cast<std::size_t>(chunks.count));
  for (std::size_t k = 0; k < kept.first.size(); ++k) {
    const std::int64_t u1 = grid.cell_of(kept.x_first[k], kept.y_first[k]) / grid.nv();
    const std::int64_t u2 = grid.cell_of(kept.x_second[k], kept.y_second[k]) / grid.nv();
    if (u1 - u2 > 1 || u2 - u1 > 1) continue;
    const std::int32_t to = chunk_rank[static_cast<std::size_t>(std::min(u1, u2) / chunks.stripes_per_chunk)];
    if (to == rank || to == kNoRank) continue;
    const std::uint64_t key = pair_key(kept.first[k], kept.second[k]);
    auto& values = out[static_cast<std::size_t>(to)];
    values.push_back(pack_pair(static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>(key)));
    values.push_back(kept.xi[k]);
    if (!kept.roll.empty()) values.push_back(kept.roll[k]);
  }
  return out;
}

void unpack_arriving_pairs(PairContacts& pairs, PairRange own, std::span<const std::vector<double>> received,
                           bool rolling) {
  struct Arrived {
    std::uint64_t key;
    double xi, roll;
  };
  const std::size_t per = leaving_pair_values(rolling);
  std::vector<Arrived> arrived;
  for (const auto& values : received) {
    if (values.size() % per != 0) throw std::logic_error("a pair migration of another size than its pairs'");
    for (std::size_t v = 0; v < values.size(); v += per) {
      std::uint32_t first = 0, second = 0;
      unpack_pair(values[v], first, second);
      arrived.push_back({std::uint64_t{first} << 32 | second, values[v + 1], rolling ? values[v + 2] : 0.0});
    }
  }
  if (arrived.empty()) return;
  // One keeper sent each pair: the keys are distinct, and the order of arrival does not matter.
  std::sort(arrived.begin(), arrived.end(), [](const Arrived& a, const Arrived& b) { return a.key < b.key; });
  for (std::size_t p = own.begin; p < own.end_in(pairs.size()); ++p) {
    const std::uint64_t key = pair_key(pairs.id_first[p], pairs.id_second[p]);
    const auto it = std::lower_bound(arrived.begin(), arrived.end(), key,
                                     [](const Arrived& a, std::uint64_t k) { return a.key < k; });
    if (it == arrived.end() || it->key != key) continue;
    pairs.xi[p] = it->xi;
    if (rolling) pairs.roll[p] = it->roll;
  }
}

}  // namespace orogen
