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
// is one value per pair (PairContacts::xi, or ::roll while it is kept).
HistoryCarry index_pair_history(const PairContacts& pairs, std::span<const double> history, std::int64_t max_id);
HistoryCarry index_wall_history(const WallContacts& walls, std::int64_t max_id);

// Sets the new pairs' stable ids (from the list and discs) and their carried histories.
void carry_pair_history(PairContacts& pairs, const NeighborList& list, const Discs& discs, const HistoryCarry& old);
// Sets the new pairs' rolling histories, after carry_pair_history has set their ids.
void carry_rolling_history(PairContacts& pairs, const HistoryCarry& old);
// Sets the new wall contacts' carried histories (their disc ids are set by their search).
void carry_wall_history(WallContacts& walls, const HistoryCarry& old);

}  // namespace orogen
