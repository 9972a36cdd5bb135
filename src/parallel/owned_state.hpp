#pragma once
// The state a rank alone keeps current in its copy of the world between list builds: the
// motion of the discs it integrates, its bodies, the histories of its chunks' pairs and of its
// discs' wall contacts. Sent whole to every rank where a stage reads the whole world, and to one
// place to read the run out; before a list build only the positions and bonds go to every rank,
// the rest moves to its new keeper after the build (parallel/migration.hpp).
#include <span>
#include <vector>

#include "parallel/exchange_plan.hpp"
#include "parallel/rank_access.hpp"

namespace orogen {

// Appends rank `owner`'s state, in a fixed order, to `out`.
void pack_owned_state(RankAccess& world, const ExchangePlan& plan, int owner, std::vector<double>& out);
// Writes rank `owner`'s state, as packed, into `world`.
void unpack_owned_state(RankAccess& world, const ExchangePlan& plan, int owner, std::span<const double> in);
// How many values rank `owner`'s state packs into.
std::size_t owned_state_size(RankAccess& world, const ExchangePlan& plan, int owner);

// The same for the positions alone: of the discs rank `owner` integrates and of its bodies.
void pack_owned_positions(RankAccess& world, const ExchangePlan& plan, int owner, std::vector<double>& out);
void unpack_owned_positions(RankAccess& world, const ExchangePlan& plan, int owner, std::span<const double> in);
std::size_t owned_positions_size(RankAccess& world, const ExchangePlan& plan, int owner);

// What a list build made without the whole state reads of rank `owner`'s (parallel/migration.hpp):
// its positions and its bonds' state.
void pack_build_state(RankAccess& world, const ExchangePlan& plan, int owner, std::vector<double>& out);
void unpack_build_state(RankAccess& world, const ExchangePlan& plan, int owner, std::span<const double> in);
std::size_t build_state_size(RankAccess& world, const ExchangePlan& plan, int owner);

// The pairs of rank `owner`'s chunks of the list (disc indices, one double a pair): after a
// build over ranks each copy holds only its own (parallel/rank_step.cpp), and a whole copy
// gathers the others'. Once every rank's are in, complete_gathered_list sets the ids and
// dashpots of the pairs that came (as their keepers set them at the build).
void pack_list_pairs(RankAccess& world, const ExchangePlan& plan, int owner, std::vector<double>& out);
void unpack_list_pairs(RankAccess& world, const ExchangePlan& plan, int owner, std::span<const double> in);
std::size_t list_pairs_size(RankAccess& world, const ExchangePlan& plan, int owner);
void complete_gathered_list(RankAccess& world);

}  // namespace orogen
