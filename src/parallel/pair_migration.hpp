#pragma once
// The pairs' contact histories across a list build over ranks (docs/domain-decomposition.md,
// step 3) without any copy looking the whole list up: each rank indexes only the old pairs it
// kept and carries histories only into its own chunks of the new list; a pair that changes
// keeper goes from its old keeper, which finds the new one from the pair's discs' new stripes
// (a pair lies in the chunk of its lower stripe), to the new one, which takes the pairs its
// search listed. The receiver cannot know how many come: a count goes first.
#include <cstdint>
#include <span>
#include <vector>

#include "contact/cell_grid.hpp"
#include "contact/contact_store.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/thread_split.hpp"
#include "parallel/rank_access.hpp"

namespace orogen {

// The pairs of rank `rank`'s chunks of `cut` in the list.
PairRange rank_pairs(const NeighborList& list, const ThreadSplit& cut, int rank);

// The pairs of a rank's chunks with a history (tangential, or rolling where the store keeps it),
// recorded before a build re-orders the discs: their stable ids, histories and the positions
// of their two discs (which the build does not change).
struct KeptPairs {
  std::vector<std::int64_t> first, second;
  std::vector<double> xi, roll;  // roll: empty unless the store keeps rolling histories
  std::vector<double> x_first, y_first, x_second, y_second;
};
KeptPairs record_kept_pairs(const RankAccess& world, PairRange kept);

// Values per pair sent: its ids packed in one double, xi, and roll where kept.
std::size_t leaving_pair_values(bool rolling);

// For each rank, the kept pairs that now lie in its chunks of `cut` on `grid` (the new build's),
// packed; nothing for `rank` itself (its own pairs stay) or for a pair whose discs are now two
// or more stripes apart (no search lists it).
std::vector<std::vector<double>> pack_leaving_pairs(const KeptPairs& kept, const CellGrid& grid, const ThreadSplit& cut,
                                                    int rank);

// The histories received (by sender, as packed) written into the pairs of `own` that they name;
// a pair sent but not listed again (its discs came apart) is dropped.
void unpack_arriving_pairs(PairContacts& pairs, PairRange own, std::span<const std::vector<double>> received,
                           bool rolling);

}  // namespace orogen
