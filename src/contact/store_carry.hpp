#pragma once
// History carry-over of the contact store across a list build: the old contacts are indexed
// by stable ids before the discs are re-ordered, the new ones find their history there.
#include <cstdint>
#include <span>

#include "contact/contact_store.hpp"
#include "contact/history_carry.hpp"
#include "contact/neighbor_list.hpp"
#include "particles/discs.hpp"

namespace orogen {

// The largest stable id in the store (with the discs' own, the size of the index).
std::int64_t max_stored_id(const ContactStore& store);

// Indexes the old pair (first id, second id) and wall (disc id, wall) histories; a pair history
// is one value per pair (PairContacts::xi, or ::roll while it is kept). Only the pairs of
// `indexed` (all by default; over ranks, the ones this rank kept current).
HistoryCarry index_pair_history(const PairContacts& pairs, std::span<const double> history, std::int64_t max_id,
                                PairRange indexed = {});
HistoryCarry index_wall_history(const WallContacts& walls, std::int64_t max_id);

// Sets the new pairs' stable ids (from the list and discs).
void set_pair_ids(PairContacts& pairs, const NeighborList& list, const Discs& discs);
// Carries the histories of the new pairs of `carried` (all by default), their ids set; the
// others' are 0 (over ranks each rank carries its own chunks').
void carry_pair_history(PairContacts& pairs, const HistoryCarry& old, PairRange carried = {});
// The same for the rolling histories (sized, and 0 outside `carried`).
void carry_rolling_history(PairContacts& pairs, const HistoryCarry& old, PairRange carried = {});
// Sets the new wall contacts' carried histories (their disc ids are set by their search).
void carry_wall_history(WallContacts& walls, const HistoryCarry& old);

}  // namespace orogen
