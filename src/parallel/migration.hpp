#pragma once
// A list build over ranks without the whole state (docs/domain-decomposition.md, step 3): every
// copy receives the positions (and the bonds' state) of every rank, builds the list of one
// process, which re-orders the discs, bodies and contacts alike in every copy, and then each rank
// sends the state it kept current (motion, bodies, wall contacts' histories) to the rank that keeps it
// under the new plan: the migration. What stays with its keeper is not sent. The pairs'
// histories migrate apart (pair_migration.hpp): no copy looks up the whole list for them.
#include <cstdint>
#include <span>
#include <vector>

#include "parallel/exchange_plan.hpp"
#include "parallel/rank_access.hpp"

namespace orogen {

// Who kept each piece of state current under the plan before a build, by stable ids (the
// build changes the indices). Recorded before the build.
struct PreviousKeepers {
  std::vector<std::int32_t> disc_step, disc_wall;  // by disc id: the rank that integrated it, its wall owner
  std::vector<std::int32_t> body;                  // by body id
};
PreviousKeepers record_keepers(RankAccess& world, const ExchangePlan& plan);

// After the build and the new plan: by new index, the rank that kept each item whose keeper
// changed (kNoRank where it did not, or for a contact new in this build: the same in every copy).
struct Migration {
  std::vector<std::int32_t> disc, body, wall;
};
Migration find_migration(RankAccess& world, const PreviousKeepers& before, const ExchangePlan& after);

// The values rank `from` sends each rank (indexed by rank; empty where nothing moves).
std::vector<std::vector<double>> pack_migration(RankAccess& world, const Migration& m, const ExchangePlan& after,
                                                int from);
// How many values rank `to` receives from each rank.
std::vector<std::size_t> migration_sizes(RankAccess& world, const Migration& m, const ExchangePlan& after, int to);
// Writes what rank `to` received (indexed by sender, sized as migration_sizes) into its copy.
void unpack_migration(RankAccess& world, const Migration& m, const ExchangePlan& after, int to,
                      std::span<const std::vector<double>> received);

}  // namespace orogen
