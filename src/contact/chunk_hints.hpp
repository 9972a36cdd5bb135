#pragma once
// The hints a list build leaves for the force loop and the thread split: how many of each
// chunk's pairs touched and the first disc of each chunk. Hints only: results never
// depend on them, so they are not checkpointed.
#include "contact/cell_grid.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/pair_search.hpp"

namespace orogen {

// Sets list.chunk_touching from the search's touching counts, and list.chunk_disc from the bins:
// the count of discs in the chunks before each (exact after a sort, close without one).
void set_chunk_hints(NeighborList& list, const PairSearchResult& search, const CellBins& bins);

}  // namespace orogen
