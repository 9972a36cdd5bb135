#pragma once
// The ranks whose chunks can name each disc, from the stripes alone (docs/domain-decomposition.md,
// "The second half, as it would be built"): a pair lies in the chunk of its lower stripe and
// reaches one stripe past it, so a disc of stripe u can only be named by chunk(u)'s pairs and,
// where u is its chunk's first stripe, by chunk(u) - 1's. A plan made from these is a superset of
// the plan made from the whole list, and needs no rank's pairs: what a rank that builds only its
// own chunks of the list needs: the step over ranks plans from these after a list build.
#include <cstdint>
#include <vector>

#include "contact/cell_grid.hpp"
#include "contact/thread_split.hpp"
#include "parallel/exchange_plan.hpp"
#include "particles/discs.hpp"

namespace orogen {

// By disc index: the rank of the even and of the odd chunk that can name the disc (kNoRank where
// none), for the grid of a build (its chunks as pair_chunks makes them) and a cut of its chunks
// between ranks.
using StripeRanks = ChunkRanks;
StripeRanks stripe_chunk_ranks(const CellGrid& grid, const Discs& discs, const ThreadSplit& cut);

}  // namespace orogen
