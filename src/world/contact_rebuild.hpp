#pragma once
// A list build: the neighbour search lists candidates (pairs, wall contacts), then the
// contact store is set for them. Each step is a function of its own; this file only runs
// them in order (the order of a build is part of the bitwise results).
#include <vector>

#include "boundary/wall.hpp"
#include "contact/history_carry.hpp"
#include "contact/contact_law.hpp"
#include "contact/contact_store.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/pair_search.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Re-orders discs in cell order (if `sort`), lists the candidate pairs and wall contacts,
// carries the contact histories over by stable ids, sets each contact's dashpot and records
// the reference positions. With a non-finite position it stops at once and changes nothing.
BuildStats rebuild_contacts(NeighborList& list, ContactStore& store, Discs& discs, Clusters& clusters,
                            const std::vector<Wall>& walls, const ContactLaw& law, double dt, bool sort);

// The same build in two parts around the pair search, for a build whose chunks are searched
// apart (over ranks, docs/domain-decomposition.md): begin_rebuild indexes the old histories
// and bins (and sorts) the discs; the caller fills list.first, second and chunk_start from the
// bins (search_pairs, or chunks searched apart and joined) and hands what the search saw to
// take_found_pairs; finish_rebuild does the rest. rebuild_contacts is these in turn. Over
// ranks a rank indexes only the old pairs it kept current (`indexed`) and carries histories
// only into the new pairs it keeps (`carried`, its chunks under the cut made from the list's
// shape); the histories of the pairs that change keeper travel between the ranks
// (parallel/pair_migration).
struct PendingBuild {
  bool finite = true;  // false: a position is not finite, nothing was changed, stop
  bool sort = false;
  bool rolling = false;
  HistoryCarry pair_history, wall_history, rolling_history;
  CellBins bins;
  PairSearchResult search;  // what the search saw (take_found_pairs)
};
PendingBuild begin_rebuild(const NeighborList& list, const ContactStore& store, Discs& discs, Clusters& clusters,
                           bool sort, PairRange indexed = {});
// What the search saw, kept for finish_rebuild; the chunk hints set from it (they cut the
// ranks' shares, so they come before the rest).
void take_found_pairs(PendingBuild& build, const PairSearchResult& search, NeighborList& list);
BuildStats finish_rebuild(PendingBuild& build, NeighborList& list, ContactStore& store, Discs& discs,
                          Clusters& clusters, const std::vector<Wall>& walls, const ContactLaw& law, double dt,
                          PairRange carried = {});

// Whether the next step must rebuild: the list is stale, or some disc (displacement `moved`,
// from integration) plus the walls moved more than half the skin since the last build.
bool contacts_stale(const NeighborList& list, const Discs& discs, const std::vector<Wall>& walls, double moved);

}  // namespace orogen
