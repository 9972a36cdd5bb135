#include "parallel/emulated_ranks.hpp"

#include <stdexcept>

#include "parallel/owned_state.hpp"

namespace orogen {

EmulatedRanks::EmulatedRanks(const World& world, int ranks, RankCut cut) : mailbox_(ranks) {
  if (ranks < 1) throw std::invalid_argument("a run over ranks needs at least one rank");
  check_steppable_over_ranks(world);  // the copies drop their hooks
  for (int r = 0; r < ranks; ++r) {
    copies_.push_back(std::make_unique<World>(world));
    transports_.push_back(std::make_unique<InProcessTransport>(mailbox_, r));
    steps_.push_back(std::make_unique<RankStep>(*copies_.back(), *transports_.back(), cut));
  }
}

void EmulatedRanks::advance() {
  for (const Phase phase : kStepPhases) {
    for (auto& s : steps_) s->post(phase);
    for (auto& s : steps_) s->take(phase);
  }
  if (!mailbox_.empty()) throw std::logic_error("a buffer sent in a step was never received");
}

World EmulatedRanks::gathered() {
  World whole = *copies_[0];
  const ExchangePlan& plan = steps_[0]->plan();
  if (plan.ranks == 0) return whole;  // not stepped yet: every copy is the world given
  RankAccess into(whole);
  std::vector<double> buffer;
  for (int r = 1; r < ranks(); ++r) {
    buffer.clear();
    pack_owned_state(steps_[static_cast<std::size_t>(r)]->access(), plan, r, buffer);
    unpack_owned_state(into, plan, r, buffer);
    buffer.clear();  // its chunks of the list (each copy holds only its own after a build)
    pack_list_pairs(steps_[static_cast<std::size_t>(r)]->access(), plan, r, buffer);
    unpack_list_pairs(into, plan, r, buffer);
  }
  complete_gathered_list(into);
  return whole;
}

void EmulatedRanks::drop_for_testing(Exchange e) {
  for (auto& s : steps_) s->drop_for_testing(e);
}

}  // namespace orogen
