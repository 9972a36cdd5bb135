#pragma once
// Who does what with each disc in a step cut between ranks, and so what the ranks send each
// other (docs/domain-decomposition.md). Rank r runs share r of the cut: its chunks' pair
// forces (the even ones, then the odd ones), the wall forces of its disc range, the
// integration of the free discs of its disc range and of the bodies of its body range. A
// disc's force sum must then travel, as a running sum, through the ranks that add to it in the
// one-process order: its even chunk's rank, its odd chunk's, the wall owner (if it touches a
// wall), the rank that integrates it, which adds its bonds' forces. Made at each list build
// (and when bonds were made), from the list, the bonds and the cut alone.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contact/bonds.hpp"
#include "contact/contact_store.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/thread_split.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Disc lists from one rank to another, each in ascending disc order.
class Routes {
 public:
  explicit Routes(int ranks = 0) : ranks_(ranks), lists_(static_cast<std::size_t>(ranks * ranks)) {}
  const std::vector<std::uint32_t>& operator()(int from, int to) const { return lists_[index(from, to)]; }
  void add(int from, int to, std::uint32_t disc) { lists_[index(from, to)].push_back(disc); }
  std::size_t total() const;  // discs sent over all pairs of ranks

 private:
  std::size_t index(int from, int to) const { return static_cast<std::size_t>(from * ranks_ + to); }
  int ranks_;
  std::vector<std::vector<std::uint32_t>> lists_;
};

inline constexpr std::int32_t kNoRank = -1;

struct ExchangePlan {
  int ranks = 0;
  ThreadSplit cut;
  std::uint64_t build = 0;  // the list build it was made for
  // By disc: the rank of its even chunk, of its odd chunk (kNoRank: in none), the rank whose
  // disc range holds it (its wall forces), the rank that integrates it (its body's, for a
  // member), and whether it has a wall contact.
  std::vector<std::int32_t> even_rank, odd_rank, wall_rank, step_rank;
  std::vector<std::uint8_t> touches_wall;
  // Per step, in this order:
  Routes ghosts;        // position, velocity, spin (5 doubles; and slip, with materials) of the discs a rank reads but did not move
  Routes partial_sums;  // after the even chunks: the sums a rank's odd chunk goes on with (3 doubles)
  Routes pair_sums;     // after the odd chunks: whole pair sums to the wall owner of a disc on a wall
  Routes whole_sums;    // after the walls: whole sums to the rank that integrates the disc
};

// By item, the rank whose range [bounds[r], bounds[r+1]) holds it (kNoRank outside them): a
// ThreadSplit's chunk, disc or body bounds, one range per rank.
std::vector<std::int32_t> rank_of_ranges(const std::vector<std::ptrdiff_t>& bounds, std::size_t items);

// By disc: the rank of the even and of the odd chunk whose pairs name it (kNoRank: none).
struct ChunkRanks {
  std::vector<std::int32_t> even, odd;
};
// From the whole list; std::logic_error if some disc lies in two chunks of one parity (the
// list's chunks forbid it: the sums' order would then depend on the cut).
ChunkRanks list_chunk_ranks(const NeighborList& list, const ThreadSplit& cut, std::size_t discs);

// The plan of a step cut by `cut` (one share per rank), for the list of build `build` whose
// chunks name the discs as `chunk_ranks` says (from the whole list, or a superset of it from
// the stripes: stripe_ranks.hpp). The acting bonds [0, acting_bonds) are stepped by the ranks
// that integrate either disc, after the whole sums arrive (so a bond's discs are read by both:
// ghosts).
ExchangePlan make_exchange_plan(ChunkRanks chunk_ranks, std::uint64_t build, const WallContacts& walls,
                                const Discs& discs, const Clusters& clusters, const ThreadSplit& cut,
                                const Bonds& bonds, std::size_t acting_bonds);
// The same from the whole list.
ExchangePlan make_exchange_plan(const NeighborList& list, const WallContacts& walls, const Discs& discs,
                                const Clusters& clusters, const ThreadSplit& cut, const Bonds& bonds,
                                std::size_t acting_bonds);

}  // namespace orogen
