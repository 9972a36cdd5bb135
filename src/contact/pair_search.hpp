#pragma once
// The pair search: lists the candidate pairs (discs closer than the sum of their radii plus
// the skin) from the cell bins, stripe chunk by stripe chunk. It lists candidates only; their
// state (history, dashpot) is the contact store's, filled by the list build after it.
#include <cstdint>
#include <vector>

#include "contact/cell_grid.hpp"
#include "contact/neighbor_list.hpp"
#include "particles/discs.hpp"

namespace orogen {

// What a list build tells its caller: whether the positions were finite, and the worst
// overlap (the sign of a blow-up).
struct BuildStats {
  double max_overlap_ratio = 0;  // largest overlap divided by the smaller radius
  std::uint32_t worst_a = 0, worst_b = 0;
  bool finite = true;
};

// What the search saw besides the pairs: per chunk how many touched (listed first; the
// chunk_touching hint), how many stripes make a chunk, and the worst overlap.
struct PairSearchResult {
  std::vector<std::size_t> touching;
  std::int64_t stripes_per_chunk = 1;
  BuildStats stats;
};

// The most chunks a pair list has (fewer on a short domain): a number of the geometry alone,
// so that the order of the sums does not depend on threads or ranks (a rank's slab is whole
// chunks, so it also bounds the ranks of one run).
inline constexpr std::int64_t kMaxPairChunks = 64;

// How a grid's stripes make chunks: stripes_per_chunk whole stripes each (the last may be
// shorter), at most kMaxPairChunks chunks.
struct PairChunks {
  std::int64_t stripes_per_chunk = 1;
  std::int64_t count = 0;
};
PairChunks pair_chunks(const CellGrid& grid);

// One chunk's pairs as its search lists them: those that touch, then those apart, each in
// search order (the lower stable id first), and the chunk's worst overlap.
struct ChunkPairs {
  std::vector<std::uint32_t> first, second;
  std::vector<std::uint32_t> apart_first, apart_second;
  BuildStats stats;
};

// Searches chunks [begin, end) of the bins: the pairs whose lower stripe lies in them, which
// read the discs of those stripes and of the one stripe after. A chunk's pairs do not depend
// on which other chunks are searched with it (a rank's share of the list over ranks).
std::vector<ChunkPairs> search_pair_chunks(const CellBins& bins, const Discs& discs, double skin, std::int64_t begin,
                                           std::int64_t end);

// The chunks cut into `shares` ranges of whole chunks with about as many discs each (a disc
// counted in the chunk of its stripe), as `shares` + 1 bounds: share r searches chunks
// [bounds[r], bounds[r + 1]). A rule of the bins alone, so alike in every copy; any cut lists
// the same pairs (only the balance of the search changes).
std::vector<std::int64_t> chunk_ranges_by_discs(const CellBins& bins, int shares);

// Joins every chunk's pairs, in chunk order, into list.first, second and chunk_start, and
// tells what the search saw (the worst overlap: the first chunk's on a tie).
PairSearchResult join_pair_chunks(NeighborList& list, const std::vector<ChunkPairs>& found,
                                  std::int64_t stripes_per_chunk);

// Sets list.first, second (the lower stable id first; in each chunk the pairs that touch
// first, then those apart, each part in search order) and chunk_start from the bins: every
// chunk searched, then joined.
PairSearchResult search_pairs(NeighborList& list, const CellBins& bins, const Discs& discs);

}  // namespace orogen
