#pragma once
// One rank of a run cut between MPI ranks (docs/domain-decomposition.md, step 2): its own copy
// of the World, stepped by a RankStep over an MpiTransport. Every rank must build the same World
// (the same construction, the same seed) and call each member below in the same order: each is
// collective. Rank 0 gathers the whole state, as one process holds it, to write it out or to
// compare it with a run of one process (tests/mpi/test_mpi_ranks.cpp).
#include <memory>
#include <optional>

#include "parallel/mpi_transport.hpp"
#include "parallel/rank_step.hpp"

namespace orogen {

class MpiRank {
 public:
  // Copies `world`; std::invalid_argument if it has what a step over ranks does not run yet,
  // std::runtime_error if this build has no MPI, std::logic_error if MPI is not initialised.
  explicit MpiRank(const World& world, RankCut cut = {});
  MpiRank(const MpiRank&) = delete;
  MpiRank& operator=(const MpiRank&) = delete;

  void advance();  // one time step (every rank at once)
  // On rank 0 the whole state (its copy with every other rank's own state, sent by it);
  // elsewhere nothing. The ranks' copies are not changed.
  std::optional<World> gathered();

  int rank() const { return transport_.rank(); }
  int ranks() const { return transport_.ranks(); }
  const RankStep& step() const { return *step_; }
  MpiTransport& transport() { return transport_; }

 private:
  World world_;
  MpiTransport transport_;
  std::unique_ptr<RankStep> step_;
};

}  // namespace orogen
