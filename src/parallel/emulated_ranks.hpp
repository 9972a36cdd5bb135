#pragma once
// A run cut between K ranks, emulated in one process: K copies of the World, each stepped by its
// own RankStep, phase by phase in lockstep (every rank posts, then every rank takes), talking
// only through an in-process mailbox. A value that a rank reads and no exchange brought stays
// stale in its copy, so a test against the one-process step sees every missing exchange
// (tests/test_emulated_ranks.cpp). Step 1 of docs/domain-decomposition.md's order of work.
#include <memory>
#include <vector>

#include "parallel/rank_step.hpp"
#include "parallel/rank_transport.hpp"

namespace orogen {

class EmulatedRanks {
 public:
  // Copies `world` into `ranks` ranks; std::invalid_argument if it has what a step over ranks
  // does not run yet (a copy would drop its hooks silently: they are checked here).
  EmulatedRanks(const World& world, int ranks, RankCut cut = {});
  EmulatedRanks(const EmulatedRanks&) = delete;
  EmulatedRanks& operator=(const EmulatedRanks&) = delete;

  void advance();  // one time step on every rank
  // The whole state as one process holds it: rank 0's copy with every rank's own state in it
  // (what rank 0 would gather to write an output). The ranks' copies are not changed.
  World gathered();

  int ranks() const { return static_cast<int>(steps_.size()); }
  const RankStep& rank(int r) const { return *steps_[static_cast<std::size_t>(r)]; }
  const InProcessMailbox& mailbox() const { return mailbox_; }
  void drop_for_testing(Exchange e);

 private:
  InProcessMailbox mailbox_;
  std::vector<std::unique_ptr<World>> copies_;
  std::vector<std::unique_ptr<InProcessTransport>> transports_;
  std::vector<std::unique_ptr<RankStep>> steps_;
};

}  // namespace orogen
