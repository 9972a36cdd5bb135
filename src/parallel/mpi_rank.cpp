#include "parallel/mpi_rank.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

#include "parallel/owned_state.hpp"

namespace orogen {
namespace {

const World& supported(const World& world) {
  check_steppable_over_ranks(world);  // the copy drops its hooks
  return world;
}

}  // namespace

MpiRank::MpiRank(const World& world, RankCut cut)
    : world_(supported(world)), step_(std::make_unique<RankStep>(world_, transport_, std::move(cut))) {}

void MpiRank::advance() { step_->advance(); }

std::optional<World> MpiRank::gathered() {
  const ExchangePlan& plan = step_->plan();
  std::vector<double> buffer;
  if (rank() != 0) {
    if (plan.ranks == 0) return std::nullopt;  // not stepped yet: rank 0's copy is the world given
    pack_owned_state(step_->access(), plan, rank(), buffer);
    transport_.send(0, buffer);
    buffer.clear();  // its chunks of the list (each copy holds only its own after a build)
    pack_list_pairs(step_->access(), plan, rank(), buffer);
    transport_.send(0, buffer);
    transport_.flush();
    return std::nullopt;
  }
  World whole = world_;
  if (plan.ranks == 0) return whole;
  RankAccess into(whole);
  for (int r = 1; r < ranks(); ++r) {
    buffer.resize(owned_state_size(into, plan, r));
    transport_.receive(r, buffer);
    unpack_owned_state(into, plan, r, buffer);
    buffer.resize(list_pairs_size(into, plan, r));
    transport_.receive(r, buffer);
    unpack_list_pairs(into, plan, r, buffer);
  }
  complete_gathered_list(into);
  return whole;
}

}  // namespace orogen
